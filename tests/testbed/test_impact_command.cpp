// The `testbed impact` command's JSON handling.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "commands/impact_command.hpp"

namespace {

struct CommandRun {
    int code;
    std::string out, err;
};

CommandRun run(const std::string& input) {
    std::istringstream in(input);
    std::ostringstream out, err;
    const int code = tb::runImpactCommand(in, out, err);
    return {code, out.str(), err.str()};
}

// The DecompressionEnded hand case of test_impact.cpp: a particle sliding on
// the ground, μ = 1/4, e = 1/2, v = (1, −2): v' = (1/4, 1), p = (−3/4, 3).
const char* kOne = R"({"e":0.5,"mu":0.25,"normal":[0,1],)"
                   R"("a":{"inv_mass":1,"inv_inertia":0,"r":[0,0],"v":[1,-2],"w":0},)"
                   R"("b":{"inv_mass":0,"inv_inertia":0,"r":[0,0],"v":[0,0],"w":0}})";

}  // namespace

TEST(ImpactCommand, ResolvesOneObject) {
    const CommandRun r = run(kOne);
    ASSERT_EQ(r.code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    // 1e-14: exact rationals after O(20) roundings of order-1 numbers.
    EXPECT_NEAR(j["a"]["v"][0].get<double>(), 0.25, 1e-14);
    EXPECT_NEAR(j["a"]["v"][1].get<double>(), 1.0, 1e-14);
    EXPECT_EQ(j["a"]["w"].get<double>(), 0.0);
    EXPECT_NEAR(j["impulse"][0].get<double>(), -0.75, 1e-14);
    EXPECT_NEAR(j["impulse"][1].get<double>(), 3.0, 1e-14);
    EXPECT_EQ(j["b"]["v"][0].get<double>(), 0.0);
    EXPECT_EQ(j["case"].get<std::string>(), "decompression_ended");
}

TEST(ImpactCommand, ArrayGivesArray) {
    const CommandRun r = run(std::string("[") + kOne + "," + kOne + "]");
    ASSERT_EQ(r.code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    ASSERT_TRUE(j.is_array());
    EXPECT_EQ(j.size(), 2u);
    EXPECT_EQ(j[1]["case"].get<std::string>(), "decompression_ended");
}

TEST(ImpactCommand, InvalidInputFails) {
    const std::string one = kOne;
    auto replaced = [&](const std::string& from, const std::string& to) {
        std::string s = one;
        s.replace(s.find(from), from.size(), to);
        return s;
    };
    for (const std::string& bad : {
             std::string("{\"e\":0.5,"),                          // malformed JSON
             replaced("\"e\":0.5,", ""),                          // missing field
             replaced("\"e\":0.5,", "\"e\":0.5,\"x\":1,"),        // unknown field
             replaced("\"mu\":0.25", "\"mu\":\"0.25\""),          // wrong type
             replaced("\"normal\":[0,1]", "\"normal\":[0,1,2]"),  // wrong length
             replaced("\"normal\":[0,1]", "\"normal\":[0,2]"),    // resolveImpact refuses
             replaced("\"e\":0.5", "\"e\":1.5"),                  // resolveImpact refuses
             std::string("[") + one + ",3]",                      // bad element in an array
         }) {
        const CommandRun r = run(bad);
        EXPECT_NE(r.code, 0) << bad;
        EXPECT_TRUE(r.out.empty()) << bad;
        EXPECT_FALSE(r.err.empty()) << bad;
    }
}
