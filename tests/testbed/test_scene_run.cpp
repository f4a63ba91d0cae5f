// Shipped scenes built as worlds and stepped; `testbed run` options and its
// JSON report.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <functional>
#include <map>
#include <sstream>
#include <string>

#include "run_command.hpp"
#include "scene_build.hpp"
#include "scene_loader.hpp"

namespace {

const std::string kAssets = TB_TEST_ASSETS_DIR;

std::vector<std::string> sceneNames() {
    std::vector<std::string> names;
    for (const auto& s : tb::listScenes(kAssets)) names.push_back(s.first);
    return names;
}

class EveryScene : public ::testing::TestWithParam<std::string> {};

// Five simulated seconds with every body state finite after every step.
TEST_P(EveryScene, BuildsAndRunsFiveSecondsFinite) {
    const std::string name = GetParam();
    tb::SceneDesc desc = tb::loadSceneDesc(name, kAssets);
    long steps = std::lround(5.0 / desc.dt);
    tb::Scene scene = tb::buildScene(desc);
    ASSERT_EQ(scene.bodies.size(), desc.bodies.size());
    ASSERT_EQ(scene.world->bodyCount(), static_cast<int>(desc.bodies.size()));
    ASSERT_EQ(scene.world->jointCount(), static_cast<int>(desc.joints.size()));
    for (long i = 0; i < steps; ++i) {
        scene.world->step(desc.dt);
        for (i2d::BodyId id : scene.world->bodies()) {
            ASSERT_TRUE(i2d::isFinite(scene.world->position(id)) && std::isfinite(scene.world->angle(id)) &&
                        i2d::isFinite(scene.world->linearVelocity(id)) &&
                        std::isfinite(scene.world->angularVelocity(id)))
                << name << ": non-finite state after step " << i + 1;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Shipped, EveryScene, ::testing::ValuesIn(sceneNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

TEST(RunCommand, JsonHasEveryField) {
    std::ostringstream out, err;
    int rc = tb::runRunCommand({"stack5", "--steps", "10", "--json", "--assets", kAssets}, out, err);
    ASSERT_EQ(rc, 0) << err.str();
    nlohmann::json j = nlohmann::json::parse(out.str());
    EXPECT_EQ(j.at("scene"), "stack5");
    EXPECT_EQ(j.at("steps"), 10);
    EXPECT_NEAR(j.at("dt").get<double>(), 1.0 / 60.0, 1e-6);
    for (const char* k : {"median", "min", "max"}) {
        ASSERT_TRUE(j.at("ms_per_step").at(k).is_number()) << k;
        EXPECT_GE(j["ms_per_step"][k].get<double>(), 0.0);
    }
    EXPECT_LE(j["ms_per_step"]["min"].get<double>(), j["ms_per_step"]["median"].get<double>());
    EXPECT_LE(j["ms_per_step"]["median"].get<double>(), j["ms_per_step"]["max"].get<double>());
    EXPECT_EQ(j.at("bodies"), 6);
    EXPECT_TRUE(j.at("contacts").is_number_integer());
    EXPECT_TRUE(j.at("max_contacts").is_number_integer());
    EXPECT_GE(j.at("max_penetration").get<double>(), 0.0);
    for (const char* k : {"initial", "final", "max"}) ASSERT_TRUE(j.at("energy").at(k).is_number()) << k;
    EXPECT_GE(j["energy"]["max"].get<double>(), j["energy"]["initial"].get<double>());
    EXPECT_EQ(j.at("nan"), false);
    const auto& top = j.at("named").at("top");
    for (const char* k : {"x0", "y0", "angle0", "x", "y", "angle", "vx", "vy", "w"})
        ASSERT_TRUE(top.at(k).is_number()) << k;
    EXPECT_FLOAT_EQ(top["y0"].get<float>(), 14.0f);
    EXPECT_TRUE(j["named"].contains("bottom"));
    // Ten steps of free fall from rest: the top box has moved down.
    EXPECT_LT(top["y"].get<double>(), 14.0);
    EXPECT_LT(top["vy"].get<double>(), 0.0);
}

// The contact stiffness options reach the world and the report names them.
TEST(RunCommand, ContactStiffnessOptionsAreAppliedAndReported) {
    std::ostringstream out, err;
    const int rc = tb::runRunCommand({"stack5", "--steps", "2", "--json", "--contact-hertz", "50",
                                      "--contact-damping-ratio", "16.7", "--assets", kAssets},
                                     out, err);
    ASSERT_EQ(rc, 0) << err.str();
    const nlohmann::json j = nlohmann::json::parse(out.str());
    EXPECT_FLOAT_EQ(j.at("settings").at("contact_hertz").get<float>(), 50.0f);
    EXPECT_FLOAT_EQ(j.at("settings").at("contact_damping_ratio").get<float>(), 16.7f);
    EXPECT_TRUE(j.at("settings").at("exact_column_tilt").get<bool>());  // on by default
}

// `--exact-column-tilt off` reaches the world (the columns' tilt left to the
// soft rows) and the report names it.
TEST(RunCommand, ExactColumnTiltOptionIsAppliedAndReported) {
    std::ostringstream out, err;
    const int rc = tb::runRunCommand(
        {"stack5", "--steps", "2", "--json", "--exact-column-tilt", "off", "--assets", kAssets}, out, err);
    ASSERT_EQ(rc, 0) << err.str();
    const nlohmann::json j = nlohmann::json::parse(out.str());
    EXPECT_FALSE(j.at("settings").at("exact_column_tilt").get<bool>());
    EXPECT_FALSE(tb::parseRunOptions({"x", "--exact-column-tilt", "off"}).overrides.exactColumnTilt.value_or(true));
}

// `--engine box2d` prints the same report: the same keys at every level, the
// same body and joint counts, and the notes say what Box2D could not express.
TEST(RunCommand, Box2DReportHasTheSameFields) {
    if (!tb::box2dAvailable()) GTEST_SKIP() << "testbed built without Box2D 2.4.1";
    auto run = [](const std::string& engine) {
        std::ostringstream out, err;
        int rc = tb::runRunCommand({"heavy_chain", "--steps", "10", "--json", "--engine", engine, "--assets", kAssets},
                                   out, err);
        EXPECT_EQ(rc, 0) << err.str();
        return nlohmann::json::parse(out.str());
    };
    nlohmann::json a = run("impulse2d"), b = run("box2d");
    EXPECT_EQ(a["engine"], "impulse2d");
    EXPECT_EQ(b["engine"], "box2d");
    std::function<void(const nlohmann::json&, const nlohmann::json&, const std::string&)> sameKeys =
        [&](const nlohmann::json& x, const nlohmann::json& y, const std::string& path) {
            if (!x.is_object()) return;
            for (auto it = x.begin(); it != x.end(); ++it) {
                if (it.key() == "settings") continue;  // each engine's own settings
                ASSERT_TRUE(y.contains(it.key())) << path + it.key();
                if (it.key() == "profile") continue;  // Impulse2D's stage timing, null for Box2D
                sameKeys(it.value(), y[it.key()], path + it.key() + ".");
            }
        };
    sameKeys(a, b, "");
    sameKeys(b, a, "");
    EXPECT_EQ(a["bodies"], b["bodies"]);
    EXPECT_EQ(a["joints"], b["joints"]);
    EXPECT_EQ(b["settings"]["velocity_iterations"], 8);
    EXPECT_EQ(b["settings"]["position_iterations"], 3);
    // Same scene, same mass properties: the initial energy agrees to float rounding.
    EXPECT_NEAR(a["energy"]["initial"].get<double>(), b["energy"]["initial"].get<double>(),
                1e-6 * std::abs(a["energy"]["initial"].get<double>()));
    ASSERT_FALSE(b["notes"].empty());
    EXPECT_NE(b["notes"][0].get<std::string>().find("skin"), std::string::npos);
}

TEST(RunCommand, Box2DIterationsFromTheCommandLine) {
    tb::RunOptions o = tb::parseRunOptions(
        {"x", "--engine", "box2d", "--velocity-iterations", "16", "--position-iterations", "6"});
    EXPECT_EQ(o.engine, tb::EngineKind::box2d);
    EXPECT_EQ(o.box2dSettings().velocityIterations, 16);
    EXPECT_EQ(o.box2dSettings().positionIterations, 6);
    EXPECT_EQ(tb::parseRunOptions({"x"}).box2dSettings().velocityIterations, 8);
    EXPECT_THROW(tb::parseRunOptions({"x", "--engine", "bullet"}), tb::UsageError);
}

TEST(RunCommand, InitialEnergyIsPotentialOfTheStack) {
    // stack5: 5 boxes of 1.2 kg at heights 2, 5, 8, 11, 14 m under g = 10:
    // E = Σ m g y = 1.2·10·40 = 480 J, at rest so no kinetic part. The
    // density is rounded to 6 decimals in the file: relative error < 3e-6.
    std::ostringstream out, err;
    ASSERT_EQ(tb::runRunCommand({"stack5", "--steps", "0", "--json", "--assets", kAssets}, out, err), 0) << err.str();
    nlohmann::json j = nlohmann::json::parse(out.str());
    EXPECT_NEAR(j["energy"]["initial"].get<double>(), 480.0, 480.0 * 1e-5);
    EXPECT_EQ(j["energy"]["initial"], j["energy"]["final"]);
}

TEST(RunCommand, SecondsAndOverrides) {
    std::ostringstream out, err;
    int rc = tb::runRunCommand({"bounce", "--seconds", "0.5", "--json", "--substeps", "2", "--correction", "split",
                                "--impact", "velocity_bias", "--sleep", "on", "--velocity-iterations", "5",
                                "--position-iterations", "1", "--assets", kAssets},
                               out, err);
    ASSERT_EQ(rc, 0) << err.str();
    nlohmann::json j = nlohmann::json::parse(out.str());
    EXPECT_EQ(j["steps"], 30);  // 0.5 s at 60 Hz

    tb::RunOptions o = tb::parseRunOptions({"x", "--substeps", "2", "--correction", "baumgarte", "--impact",
                                            "closed_form", "--sleep", "off", "--velocity-iterations", "25",
                                            "--position-iterations", "0"});
    i2d::WorldSettings s;
    o.overrides.applyTo(s);
    EXPECT_EQ(s.substeps, 2);
    EXPECT_EQ(s.positionCorrection, i2d::PositionCorrection::baumgarte);
    EXPECT_EQ(s.impactModel, i2d::ImpactModel::closed_form);
    EXPECT_FALSE(s.enableSleep);
    EXPECT_EQ(s.velocityIterations, 25);
    EXPECT_EQ(s.positionIterations, 0);
}

TEST(RunCommand, BadArgumentsAreRefused) {
    auto rc = [](std::vector<std::string> args) {
        std::ostringstream out, err;
        args.push_back("--assets");
        args.push_back(kAssets);
        return tb::runRunCommand(args, out, err);
    };
    EXPECT_EQ(rc({"stack5", "--steps", "-1"}), 2);
    EXPECT_EQ(rc({"stack5", "--steps", "ten"}), 2);
    EXPECT_EQ(rc({"stack5", "--correction", "magic"}), 2);
    EXPECT_EQ(rc({"stack5", "--sleep", "maybe"}), 2);
    EXPECT_EQ(rc({"stack5", "--steps", "1", "--seconds", "1"}), 2);
    EXPECT_EQ(rc({"stack5", "--frobnicate"}), 2);
    EXPECT_EQ(rc({}), 2);
    EXPECT_EQ(rc({"no_such_scene"}), 1);
}

TEST(ListCommand, OneLinePerScene) {
    std::ostringstream out, err;
    ASSERT_EQ(tb::runListCommand({"--assets", kAssets}, out, err), 0) << err.str();
    std::istringstream lines(out.str());
    std::string line;
    int n = 0;
    bool sawStack = false;
    while (std::getline(lines, line)) {
        ++n;
        if (line.rfind("stack5 ", 0) == 0) sawStack = line.find("Tamis and Maggiore (2015)") != std::string::npos;
    }
    EXPECT_EQ(n, static_cast<int>(tb::listScenes(kAssets).size()));
    EXPECT_TRUE(sawStack);
}

}  // namespace
