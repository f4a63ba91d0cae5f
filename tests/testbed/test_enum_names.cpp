// The enum name tables: every value has one name, and parsing a name gives
// back its value, so the scene loader, the command line, the JSON report and
// the viewer all agree.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "enum_names.hpp"

namespace {

template <class E>
void expectRoundTrip() {
    std::set<std::string> seen;
    for (const auto& e : tb::enumNames<E>()) {
        EXPECT_TRUE(seen.insert(e.name).second) << "duplicate name " << e.name;
        EXPECT_STREQ(tb::enumName(e.value), e.name);
        EXPECT_EQ(tb::enumFromName<E>(e.name), e.value) << e.name;
    }
    EXPECT_FALSE(tb::enumFromName<E>("no_such_name").has_value());
}

TEST(EnumNames, EveryTableRoundTrips) {
    expectRoundTrip<i2d::PositionCorrection>();
    expectRoundTrip<i2d::ImpactModel>();
    expectRoundTrip<i2d::BodyType>();
    expectRoundTrip<i2d::ShapeType>();
    expectRoundTrip<i2d::JointType>();
    expectRoundTrip<tb::EngineKind>();
    expectRoundTrip<tb::ErrorMetric>();
}

// The names are the scene format's and the JSON report's: pinned here.
TEST(EnumNames, NamesAreTheDocumentedOnes) {
    EXPECT_STREQ(tb::enumName(i2d::PositionCorrection::soft_step), "soft_step");
    EXPECT_STREQ(tb::enumName(i2d::PositionCorrection::baumgarte), "baumgarte");
    EXPECT_STREQ(tb::enumName(i2d::PositionCorrection::split), "split");
    EXPECT_STREQ(tb::enumName(i2d::ImpactModel::closed_form), "closed_form");
    EXPECT_STREQ(tb::enumName(i2d::ImpactModel::velocity_bias), "velocity_bias");
    EXPECT_STREQ(tb::enumName(i2d::BodyType::dynamic_body), "dynamic");
    EXPECT_STREQ(tb::enumName(i2d::BodyType::static_body), "static");
    EXPECT_STREQ(tb::enumName(i2d::BodyType::kinematic_body), "kinematic");
    EXPECT_STREQ(tb::enumName(i2d::JointType::distance), "distance");
    EXPECT_STREQ(tb::enumName(i2d::JointType::revolute), "revolute");
    EXPECT_STREQ(tb::enumName(i2d::JointType::gear), "gear");
    EXPECT_EQ(tb::enumNames<i2d::JointType>().size(), 9u);
    EXPECT_STREQ(tb::engineName(tb::EngineKind::box2d), "box2d");
    EXPECT_STREQ(tb::errorMetricName(tb::ErrorMetric::energy_drift), "energy_drift");
    EXPECT_STREQ(tb::errorMetricName(tb::ErrorMetric::none), "");
}

TEST(EnumNames, ListsForMessages) {
    EXPECT_EQ(tb::enumNameList<i2d::PositionCorrection>(), "soft_step, baumgarte or split");
    EXPECT_EQ(tb::enumNameList<i2d::BodyType>("\"", ", ", ", "), "\"dynamic\", \"static\", \"kinematic\"");
}

}  // namespace
