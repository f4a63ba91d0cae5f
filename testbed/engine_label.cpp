// Testbed — an engine and its settings in words (see engine_label.hpp).
#include "engine_label.hpp"

#include "enum_names.hpp"

namespace tb {

std::string engineSettingsLabel(EngineKind engine, const i2d::WorldSettings& s, const Box2DSettings& box2d) {
    const std::string sleep = s.enableSleep ? "sleep on" : "sleep off";
    if (engine == EngineKind::box2d)
        return "box2d 2.4.1: " + std::to_string(box2d.velocityIterations) + " velocity + " +
               std::to_string(box2d.positionIterations) + " position iterations, " + sleep;
    std::string label = std::string(enumName(engine)) + ": " + enumName(s.positionCorrection) + ", ";
    switch (s.positionCorrection) {
        case i2d::PositionCorrection::soft_step: label += std::to_string(s.substeps) + " substeps"; break;
        case i2d::PositionCorrection::baumgarte: label += std::to_string(s.velocityIterations) + " iterations"; break;
        case i2d::PositionCorrection::split:
            label += std::to_string(s.velocityIterations) + " + " + std::to_string(s.positionIterations) +
                     " iterations";
            break;
    }
    return label + ", " + enumName(s.impactModel) + ", " + sleep;
}

}  // namespace tb
