// Validation suite — what the case files share: the units and step of every
// scene built in code, scene-building helpers and the measurements taken from
// body samples (zero crossings, fitted accelerations).
#pragma once

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "cases.hpp"

namespace val {

using tb::EngineKind;

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kG = 10.0;          // |g| of every scene here (m/s²)
inline constexpr float kDt = 1.0f / 60.0f;  // every scene here steps at 60 Hz
// Float spacing (ulp) at 1: 2⁻²³. Rounding bounds below are written as
// multiples of the ulp of the largest magnitude involved.
inline constexpr double kEps = 1.1920928955078125e-07;

inline bool isBox2D(EngineKind kind) { return kind == EngineKind::box2d; }

/// The (sub)step of each engine's integrator and the number of them per step:
/// Impulse2D's soft step integrates `substeps` times per step; Box2D 2.4.1 once.
struct Integrator {
    double h;
    int perStep;
};
inline Integrator integrator(EngineKind kind, const tb::SceneDesc& desc) {
    const int n = isBox2D(kind) ? 1 : desc.settings.substeps;
    return {static_cast<double>(desc.dt) / n, n};
}

// ---------------------------------------------------------------------------
// Scenes built in code

inline tb::ShapeDesc circleShape(float radius, float density, float friction, float restitution) {
    tb::ShapeDesc s;
    s.type = i2d::ShapeType::circle;
    s.circle = {{0.0f, 0.0f}, radius};
    s.def.density = density;
    s.def.friction = friction;
    s.def.restitution = restitution;
    return s;
}

inline tb::ShapeDesc boxShape(float hx, float hy, float density, float friction, float restitution) {
    tb::ShapeDesc s;
    s.type = i2d::ShapeType::polygon;
    s.polygon = i2d::makeBox(hx, hy);
    s.def.density = density;
    s.def.friction = friction;
    s.def.restitution = restitution;
    return s;
}

inline tb::BodyDesc body(std::string name, i2d::BodyType type, i2d::Vec2 position, std::vector<tb::ShapeDesc> shapes) {
    tb::BodyDesc b;
    b.name = std::move(name);
    b.def.type = type;
    b.def.position = position;
    b.shapes = std::move(shapes);
    return b;
}

inline tb::SceneDesc emptyScene(const std::string& name, i2d::Vec2 gravity) {
    tb::SceneDesc d;
    d.name = name;
    d.dt = kDt;
    d.settings.gravity = gravity;
    d.settings.enableSleep = false;
    return d;
}

inline int indexOf(const tb::SceneDesc& desc, const std::string& name) {
    for (std::size_t i = 0; i < desc.bodies.size(); ++i)
        if (desc.bodies[i].name == name) return static_cast<int>(i);
    throw std::runtime_error(desc.name + ": no body named " + name);
}

/// Step `sim` `steps` times, calling f(t, sim) after each step (t = time after it).
template <class F>
void run(tb::Simulation& sim, const tb::SceneDesc& desc, long steps, F f) {
    for (long i = 1; i <= steps; ++i) {
        sim.step(desc.dt);
        f(static_cast<double>(i) * desc.dt, sim);
    }
}

inline std::unique_ptr<tb::Simulation> make(const tb::SceneDesc& desc, EngineKind kind) {
    return tb::makeSimulation(desc, kind);
}

// ---------------------------------------------------------------------------
// Measurement helpers

/// Times at which a signal crosses zero upwards, by linear interpolation
/// between samples (at a crossing of a smooth oscillation the curvature
/// vanishes, so the interpolation error is third order in the step).
struct UpCrossings {
    std::vector<double> times;
    double lastT = 0.0, lastS = 0.0;
    bool first = true;
    void add(double t, double s) {
        if (!first && lastS < 0.0 && s >= 0.0) times.push_back(lastT + (t - lastT) * (-lastS) / (s - lastS));
        first = false;
        lastT = t;
        lastS = s;
    }
    /// Mean period over the whole crossings recorded (NaN with fewer than 2).
    double period() const {
        if (times.size() < 2) return kNone;
        return (times.back() - times.front()) / static_cast<double>(times.size() - 1);
    }
};

/// Least-squares fit s(t) = c0 + c1 t + c2 t²; returns the acceleration 2 c2.
/// Semi-implicit Euler under a constant force samples an exact quadratic in
/// time, so the fit has no truncation error of its own.
inline double fittedAcceleration(const std::vector<double>& t, const std::vector<double>& s) {
    const std::size_t n = t.size();
    if (n < 3) return kNone;
    double tm = 0;
    for (double x : t) tm += x;
    tm /= static_cast<double>(n);
    double S[5] = {0, 0, 0, 0, 0}, R[3] = {0, 0, 0};
    for (std::size_t i = 0; i < n; ++i) {
        const double x = t[i] - tm;
        double p = 1.0;
        for (int k = 0; k < 5; ++k) {
            S[k] += p;
            if (k < 3) R[k] += p * s[i];
            p *= x;
        }
    }
    // Normal equations [S0 S1 S2; S1 S2 S3; S2 S3 S4] c = R, by Cramer's rule.
    auto det3 = [](double a, double b, double c, double d, double e, double f, double g, double h, double i) {
        return a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
    };
    const double D = det3(S[0], S[1], S[2], S[1], S[2], S[3], S[2], S[3], S[4]);
    const double c2 = det3(S[0], S[1], R[0], S[1], S[2], R[1], S[2], S[3], R[2]) / D;
    return 2.0 * c2;
}

}  // namespace val
