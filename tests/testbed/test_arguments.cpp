// The command-line argument reader shared by every testbed command: values
// accepted in range, and missing, malformed or out-of-range values refused
// with a message naming the option and (through the commands) exit code 2.
#include <gtest/gtest.h>

#include <climits>
#include <sstream>
#include <string>
#include <vector>

#include "cli/arguments.hpp"
#include "cli/settings_options.hpp"
#include "commands/impact_command.hpp"
#include "commands/list_command.hpp"
#include "commands/run_command.hpp"

namespace {

using Args = std::vector<std::string>;

// The message of the UsageError `f` throws; fails the test when it throws none.
template <class F>
std::string usageMessage(F f) {
    try {
        f();
    } catch (const tb::UsageError& e) {
        return e.what();
    }
    ADD_FAILURE() << "no UsageError";
    return {};
}

TEST(ArgReader, WalksOptionsValuesAndPlainArguments) {
    tb::ArgReader r(Args{"scene", "--steps", "12", "--json", "-", "--seconds", "-0"});
    std::vector<std::string> plain;
    long steps = 0;
    double seconds = 1;
    bool json = false;
    while (r.next()) {
        if (r.is("--steps"))
            steps = r.integer(0, 100);
        else if (r.is("--seconds"))
            seconds = r.number(-1, 1);
        else if (r.is("--json"))
            json = true;
        else if (r.isOption())
            r.rejectUnknownOption();
        else
            plain.push_back(r.current());
    }
    EXPECT_EQ(steps, 12);
    EXPECT_EQ(seconds, 0.0);
    EXPECT_TRUE(json);
    EXPECT_EQ(plain, (std::vector<std::string>{"scene", "-"}));  // "-" alone is not an option
}

TEST(ArgReader, MissingValueNamesTheOption) {
    tb::ArgReader r(Args{"--steps"});
    ASSERT_TRUE(r.next());
    EXPECT_EQ(usageMessage([&] { r.integer(0, 10); }), "--steps needs a value");
}

TEST(ArgReader, UnknownOptionIsNamed) {
    tb::ArgReader r(Args{"--frobnicate"});
    ASSERT_TRUE(r.next());
    EXPECT_EQ(usageMessage([&] { r.rejectUnknownOption(); }), "unknown option '--frobnicate'");
}

TEST(ParseInteger, AcceptsTheWholeRange) {
    EXPECT_EQ(tb::parseInteger("--n", "0", 0, 10), 0);
    EXPECT_EQ(tb::parseInteger("--n", "10", 0, 10), 10);
    EXPECT_EQ(tb::parseInteger("--n", "-7", -10, 10), -7);
    EXPECT_EQ(tb::parseInteger("--n", "2147483647", 1, INT_MAX), INT_MAX);
}

TEST(ParseInteger, WithoutAnUpperLimitSaysAtLeast) {
    EXPECT_EQ(usageMessage([] { tb::parseInteger("--every", "0", 1, INT_MAX); }),
              "--every: expected an integer of at least 1, got '0'");
    EXPECT_EQ(usageMessage([] { tb::parseInteger("--every", "2147483648", 1, INT_MAX); }),
              "--every: expected an integer of at least 1, got '2147483648'");
}

TEST(ParseInteger, RefusesWithTheOptionTheRangeAndTheValue) {
    EXPECT_EQ(usageMessage([] { tb::parseInteger("--steps", "-1", 0, 100); }),
              "--steps: expected an integer in [0, 100], got '-1'");
    EXPECT_EQ(usageMessage([] { tb::parseInteger("--steps", "101", 0, 100); }),
              "--steps: expected an integer in [0, 100], got '101'");
    for (const char* bad : {"", "ten", "1.5", "3x", " ", "99999999999999999999999"})
        EXPECT_NE(usageMessage([&] { tb::parseInteger("--steps", bad, 0, 100); }).find("--steps: "), std::string::npos)
            << bad;
}

TEST(ParseNumber, AcceptsFiniteValuesInRange) {
    EXPECT_DOUBLE_EQ(tb::parseNumber("--seconds", "0.5", 0, 10), 0.5);
    EXPECT_DOUBLE_EQ(tb::parseNumber("--seconds", "1e1", 0, 10), 10.0);
    for (const char* bad : {"", "abc", "nan", "inf", "-0.1", "10.01", "1,5"}) {
        const std::string m = usageMessage([&] { tb::parseNumber("--seconds", bad, 0, 10); });
        EXPECT_EQ(m.rfind("--seconds: expected a number in [", 0), 0u) << bad << ": " << m;
        EXPECT_NE(m.find(std::string("got '") + bad + "'"), std::string::npos) << m;
    }
}

TEST(ParseOnOff, OnlyOnAndOff) {
    EXPECT_TRUE(tb::parseOnOff("--sleep", "on"));
    EXPECT_FALSE(tb::parseOnOff("--sleep", "off"));
    EXPECT_EQ(usageMessage([] { tb::parseOnOff("--sleep", "yes"); }), "--sleep: expected on or off, got 'yes'");
}

TEST(ParseSize, WidthByHeightWithinLimits) {
    EXPECT_EQ(tb::parseSize("--size", "640x360", 16, 8192), std::make_pair(640, 360));
    EXPECT_EQ(usageMessage([] { tb::parseSize("--size", "640", 16, 8192); }), "--size: expected WxH, got '640'");
    EXPECT_EQ(usageMessage([] { tb::parseSize("--size", "640xabc", 16, 8192); }),
              "--size: expected WxH, got '640xabc'");
    EXPECT_EQ(usageMessage([] { tb::parseSize("--size", "8x8", 16, 8192); }),
              "--size: each side must be from 16 to 8192 pixels, got '8x8'");
    EXPECT_EQ(usageMessage([] { tb::parseSize("--size", "8x8", 16, INT_MAX); }),
              "--size: each side must be at least 16 pixels, got '8x8'");
}

TEST(ParseChoice, NamesFromTheEnumTable) {
    EXPECT_EQ(tb::parseChoice<i2d::PositionCorrection>("--correction", "split"), i2d::PositionCorrection::split);
    EXPECT_EQ(tb::parseChoice<tb::EngineKind>("--engine", "box2d"), tb::EngineKind::box2d);
    EXPECT_EQ(usageMessage([] { tb::parseChoice<i2d::PositionCorrection>("--correction", "magic"); }),
              "--correction: expected soft_step, baumgarte or split, got 'magic'");
    EXPECT_EQ(usageMessage([] { tb::parseChoice<i2d::ImpactModel>("--impact", "Closed_Form"); }),
              "--impact: expected closed_form or velocity_bias, got 'Closed_Form'");
}

TEST(WantsHelp, AnywhereInTheArguments) {
    EXPECT_TRUE(tb::wantsHelp({"stack5", "--steps", "3", "-h"}));
    EXPECT_TRUE(tb::wantsHelp({"--help"}));
    EXPECT_FALSE(tb::wantsHelp({"stack5", "--helpful"}));
}

TEST(SettingsOptions, ReadThroughTheReader) {
    tb::ArgReader r(Args{"--correction", "baumgarte", "--sleep", "off", "--substeps", "3", "--contact-hertz", "50",
                         "--contact-damping-ratio", "16.7", "--other"});
    tb::SettingsOverrides o;
    int consumed = 0;
    while (r.next())
        if (tb::parseSettingsOption(r, o)) ++consumed;
    EXPECT_EQ(consumed, 5);
    EXPECT_EQ(o.correction, i2d::PositionCorrection::baumgarte);
    EXPECT_EQ(o.sleep, false);
    EXPECT_EQ(o.substeps, 3);
    i2d::WorldSettings applied;
    o.applyTo(applied);
    EXPECT_EQ(applied.contactHertz, 50.0f);
    EXPECT_EQ(applied.contactDampingRatio, 16.7f);
    tb::ArgReader negative(Args{"--contact-hertz", "-1"});
    ASSERT_TRUE(negative.next());
    EXPECT_EQ(usageMessage([&] { tb::parseSettingsOption(negative, o); }).rfind("--contact-hertz: expected", 0), 0u);
    tb::ArgReader bad(Args{"--substeps", "0"});
    ASSERT_TRUE(bad.next());
    EXPECT_EQ(usageMessage([&] { tb::parseSettingsOption(bad, o); }),
              "--substeps: expected an integer in [1, 1000], got '0'");
}

struct CommandRun {
    int code;
    std::string out, err;
};

CommandRun runCommand(const Args& args) {
    std::ostringstream out, err;
    const int code = tb::runRunCommand(args, out, err);
    return {code, out.str(), err.str()};
}

// Through a command: exit code 2, one "testbed run: " prefix, the option
// named, the hint, nothing on standard output.
TEST(UsageErrors, ExitTwoWithOnePrefixNamingTheOption) {
    const struct {
        Args args;
        std::string message;
    } cases[] = {
        {{"stack5", "--steps"}, "--steps needs a value"},
        {{"stack5", "--steps", "ten"}, "--steps: expected an integer in [0, 100000000], got 'ten'"},
        {{"stack5", "--steps", "-5"}, "--steps: expected an integer in [0, 100000000], got '-5'"},
        {{"stack5", "--velocity-iterations", "1001"},
         "--velocity-iterations: expected an integer in [1, 1000], got '1001'"},
        {{"stack5", "--engine", "bullet"}, "--engine: expected impulse2d or box2d, got 'bullet'"},
        {{"stack5", "--sleep"}, "--sleep needs a value"},
        {{"stack5", "--frobnicate"}, "unknown option '--frobnicate'"},
    };
    for (const auto& c : cases) {
        const CommandRun r = runCommand(c.args);
        EXPECT_EQ(r.code, 2);
        EXPECT_EQ(r.err, "testbed run: " + c.message + "\n(see `testbed run --help`)\n");
        EXPECT_TRUE(r.out.empty());
    }
}

TEST(UsageErrors, ListRefusesArguments) {
    std::ostringstream out, err;
    EXPECT_EQ(tb::runListCommand({"extra"}, out, err), 2);
    EXPECT_EQ(err.str(), "testbed list: unexpected argument 'extra'\n(see `testbed list --help`)\n");
    std::ostringstream out2, err2;
    EXPECT_EQ(tb::runListCommand({"--assets"}, out2, err2), 2);
    EXPECT_EQ(err2.str(), "testbed list: --assets needs a value\n(see `testbed list --help`)\n");
}

TEST(Help, EveryCommandPrintsItsUsageAndSucceeds) {
    std::ostringstream out, err;
    EXPECT_EQ(tb::runRunCommand({"--help"}, out, err), 0);
    EXPECT_EQ(out.str().rfind("usage: testbed run", 0), 0u);
    std::ostringstream out2, err2;
    EXPECT_EQ(tb::runListCommand({"-h"}, out2, err2), 0);
    EXPECT_EQ(out2.str().rfind("usage: testbed list", 0), 0u);
    std::istringstream in;
    std::ostringstream out3, err3;
    EXPECT_EQ(tb::runImpactCommand({"--help"}, in, out3, err3), 0);
    EXPECT_EQ(out3.str().rfind("usage: testbed impact", 0), 0u);
    EXPECT_TRUE(err.str().empty() && err2.str().empty() && err3.str().empty());
}

}  // namespace
