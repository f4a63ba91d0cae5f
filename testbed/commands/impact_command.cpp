// Testbed — `testbed impact` (see impact_command.hpp).
#include "commands/impact_command.hpp"

#include <initializer_list>
#include <istream>
#include <nlohmann/json.hpp>
#include <ostream>
#include <stdexcept>
#include <string>

#include "impulse2d/error.hpp"
#include "impulse2d/impact.hpp"

#include "cli/arguments.hpp"

namespace tb {

namespace {

using nlohmann::json;

// Input that cannot be resolved; the message names where it is (e.g. input[2].a.r).
struct InputError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

void requireKeys(const json& j, const std::string& where, std::initializer_list<const char*> keys) {
    if (!j.is_object()) throw InputError(where + " must be an object");
    for (const char* k : keys)
        if (!j.contains(k)) throw InputError(where + " is missing \"" + k + "\"");
    for (auto it = j.begin(); it != j.end(); ++it) {
        bool known = false;
        for (const char* k : keys) known = known || it.key() == k;
        if (!known) throw InputError(where + " has unknown field \"" + it.key() + "\"");
    }
}

double number(const json& j, const std::string& where) {
    if (!j.is_number()) throw InputError(where + " must be a number");
    return j.get<double>();
}

i2d::Vec2d vec(const json& j, const std::string& where) {
    if (!j.is_array() || j.size() != 2) throw InputError(where + " must be an array of two numbers");
    return {number(j[0], where + "[0]"), number(j[1], where + "[1]")};
}

i2d::ImpactBody body(const json& j, const std::string& where) {
    requireKeys(j, where, {"inv_mass", "inv_inertia", "r", "v", "w"});
    i2d::ImpactBody b;
    b.invMass = number(j["inv_mass"], where + ".inv_mass");
    b.invInertia = number(j["inv_inertia"], where + ".inv_inertia");
    b.r = vec(j["r"], where + ".r");
    b.v = vec(j["v"], where + ".v");
    b.w = number(j["w"], where + ".w");
    return b;
}

// Output keeps the documented key order (a, b, impulse, case).
using ordered = nlohmann::ordered_json;

ordered resolveOne(const json& j, const std::string& where) {
    requireKeys(j, where, {"e", "mu", "normal", "a", "b"});
    i2d::ImpactInput in;
    in.restitution = number(j["e"], where + ".e");
    in.friction = number(j["mu"], where + ".mu");
    in.normal = vec(j["normal"], where + ".normal");
    in.a = body(j["a"], where + ".a");
    in.b = body(j["b"], where + ".b");
    i2d::ImpactResult r;
    try {
        r = i2d::resolveImpact(in);
    } catch (const i2d::Error& e) {
        throw InputError(where + ": " + e.what());
    }
    return ordered{{"a", {{"v", {r.vA.x, r.vA.y}}, {"w", r.wA}}},
                   {"b", {{"v", {r.vB.x, r.vB.y}}, {"w", r.wB}}},
                   {"impulse", {r.impulse.x, r.impulse.y}},
                   {"case", i2d::toString(r.kind)}};
}

const char* const kImpactHelp = "usage: testbed impact < INPUT\n\n"
                                "Resolve impacts read from standard input with the closed-form impact law;\n"
                                "see the impact law's documentation for the line format.\n";

}  // namespace

int runImpactCommand(const std::vector<std::string>& args, std::istream& in, std::ostream& out, std::ostream& err) {
    // Other arguments have always been ignored: the input is all on stdin.
    if (wantsHelp(args)) {
        out << kImpactHelp;
        return 0;
    }
    // ... except the scene options, which would otherwise seem to do something.
    for (const std::string& a : args)
        if (a == "--compare" || a == "--overlay" || a == "--engine" || a == "--trace")
            return reportUsageError(err, "impact",
                                    UsageError(a + " does not apply: `testbed impact` evaluates the impact law on "
                                                   "single impacts, it has no scene, engine or steps (see "
                                                   "`testbed render --compare`, `testbed run --trace`)"),
                                    "(see `testbed impact --help`)\n");
    return runImpactCommand(in, out, err);
}

int runImpactCommand(std::istream& in, std::ostream& out, std::ostream& err) {
    json input;
    try {
        input = json::parse(in);
    } catch (const json::parse_error& e) {
        err << "testbed impact: malformed JSON: " << e.what() << '\n';
        return 1;
    }
    try {
        ordered output;
        if (input.is_array()) {
            output = ordered::array();
            for (std::size_t i = 0; i < input.size(); ++i)
                output.push_back(resolveOne(input[i], "input[" + std::to_string(i) + "]"));
        } else {
            output = resolveOne(input, "input");
        }
        out << output.dump() << '\n';
    } catch (const InputError& e) {
        err << "testbed impact: " << e.what() << '\n';
        return 1;
    }
    return 0;
}

}  // namespace tb
