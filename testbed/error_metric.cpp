// Testbed — the per-scene error figure.
#include "error_metric.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <variant>

#include "enum_names.hpp"
#include "metrics.hpp"

namespace tb {

const char* errorMetricName(ErrorMetric m) { return enumName(m); }

const char* errorMetricUnit(ErrorMetric m) {
    switch (m) {
        case ErrorMetric::energy_drift: return "1";
        case ErrorMetric::none: return "";
        default: return "m";
    }
}

ErrorMetric errorMetricFor(const std::string& scene) {
    static const std::map<std::string, ErrorMetric> table = {
        {"pyramid100", ErrorMetric::max_excursion},
        {"many_pyramids", ErrorMetric::max_excursion},
        {"many_pyramids_small", ErrorMetric::max_excursion},
        {"tall_stack20", ErrorMetric::max_sway},
        {"tall_stack50", ErrorMetric::max_sway},
        {"card_house", ErrorMetric::max_excursion},
        {"rain1000", ErrorMetric::max_penetration},
        {"circle_pile1000", ErrorMetric::max_penetration},
        {"joint_grid", ErrorMetric::joint_stretch},
        {"heavy_chain", ErrorMetric::joint_stretch},
        {"bounce", ErrorMetric::rebound_error},
        {"pendulum_wave", ErrorMetric::energy_drift},
    };
    auto it = table.find(scene);
    return it == table.end() ? ErrorMetric::none : it->second;
}

ErrorTracker::ErrorTracker(const SceneDesc& desc, ErrorMetric metric) : desc_(desc), metric_(metric) {}

void ErrorTracker::start(const Simulation& sim) {
    worst_ = 0.0;
    const int n = sim.bodyCount();
    switch (metric_) {
        case ErrorMetric::max_excursion:
        case ErrorMetric::max_sway:
            for (int i = 0; i < n; ++i) {
                BodySample s = sim.sample(i);
                if (!s.dynamic) continue;
                dynamic_.push_back(i);
                start_.push_back(s);
            }
            break;
        case ErrorMetric::rebound_error: {
            float ground = 0.0f;
            for (const BodyDesc& b : desc_.bodies)
                if (b.def.type == i2d::BodyType::static_body)
                    for (const ShapeDesc& sh : b.shapes) ground = std::max(ground, sh.def.restitution);
            for (int i = 0; i < n; ++i) {
                const BodyDesc& b = desc_.bodies[static_cast<std::size_t>(i)];
                if (b.name.empty() || b.def.type != i2d::BodyType::dynamic_body || b.shapes.empty()) continue;
                BodySample s = sim.sample(i);
                Ball ball;
                ball.index = i;
                ball.restitution = std::max(b.shapes.front().def.restitution, ground);
                ball.y0 = ball.lowest = ball.apex = s.y;
                balls_.push_back(ball);
            }
            break;
        }
        case ErrorMetric::energy_drift: {
            const i2d::Vec2 g = desc_.settings.gravity;
            energy0_ = computeEnergy(sim, g).total();
            swing_ = 0.0;
            for (const JointDesc& j : desc_.joints) {
                const auto* d = std::get_if<i2d::DistanceJointDef>(&j.def);
                if (!d) continue;
                BodySample a = sim.sample(j.bodyA), b = sim.sample(j.bodyB);
                i2d::Vec2 anchorLocal = d->localAnchorA;
                if (!b.dynamic) {
                    std::swap(a, b);
                    anchorLocal = d->localAnchorB;
                }
                if (a.dynamic || !b.dynamic) continue;
                const float c = std::cos(a.angle), sn = std::sin(a.angle);
                const float anchorY = a.y + sn * anchorLocal.x + c * anchorLocal.y;
                const float lowest = anchorY - d->length;
                swing_ += double(b.mass) * std::hypot(g.x, g.y) * std::max(0.0f, b.y - lowest);
            }
            break;
        }
        default: break;
    }
}

void ErrorTracker::observe(const Simulation& sim, float penetration, float jointError) {
    switch (metric_) {
        case ErrorMetric::max_excursion:
            for (std::size_t k = 0; k < dynamic_.size(); ++k) {
                BodySample s = sim.sample(dynamic_[k]);
                worst_ = std::max(worst_, double(std::hypot(s.x - start_[k].x, s.y - start_[k].y)));
            }
            break;
        case ErrorMetric::max_sway:
            for (std::size_t k = 0; k < dynamic_.size(); ++k)
                worst_ = std::max(worst_, double(std::abs(sim.sample(dynamic_[k]).x - start_[k].x)));
            break;
        case ErrorMetric::max_penetration: worst_ = std::max(worst_, double(penetration)); break;
        case ErrorMetric::joint_stretch: worst_ = std::max(worst_, double(jointError)); break;
        case ErrorMetric::rebound_error:
            for (Ball& ball : balls_) {
                BodySample s = sim.sample(ball.index);
                if (ball.phase == 0) {
                    ball.lowest = std::min(ball.lowest, s.y);
                    if (s.vy > 0.0f && ball.lowest < ball.y0) {
                        ball.phase = 1;
                        ball.apex = s.y;
                    }
                } else if (ball.phase == 1) {
                    ball.lowest = std::min(ball.lowest, s.y);
                    ball.apex = std::max(ball.apex, s.y);
                    if (s.vy <= 0.0f) ball.phase = 2;
                }
            }
            break;
        case ErrorMetric::energy_drift:
            worst_ = std::max(worst_, std::abs(computeEnergy(sim, desc_.settings.gravity).total() - energy0_));
            break;
        case ErrorMetric::none: break;
    }
}

bool errorMetricHasCollapse(ErrorMetric m) { return m == ErrorMetric::max_excursion || m == ErrorMetric::max_sway; }

ErrorValue ErrorTracker::result(const Simulation& sim) const {
    ErrorValue r{metric_, worst_};
    if (errorMetricHasCollapse(metric_)) {
        std::size_t moved = 0;
        for (std::size_t k = 0; k < dynamic_.size(); ++k)
            if (std::abs(sim.sample(dynamic_[k]).x - start_[k].x) > ErrorValue::kCollapseDistance) ++moved;
        r.collapsed = moved >= std::max<std::size_t>(1, dynamic_.size() / 100);
    }
    if (metric_ == ErrorMetric::rebound_error) {
        r.value = 0.0;
        for (const Ball& ball : balls_) {
            const double drop = ball.y0 - ball.lowest;
            const double rebound = ball.phase == 0 ? 0.0 : ball.apex - ball.lowest;
            const double expected = double(ball.restitution) * ball.restitution * drop;
            r.value = std::max(r.value, std::abs(rebound - expected));
        }
    } else if (metric_ == ErrorMetric::energy_drift) {
        r.value = swing_ > 0.0 ? worst_ / swing_ : worst_;
    }
    return r;
}

}  // namespace tb
