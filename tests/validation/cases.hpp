// Validation suite — every case defined once: a scene (built in code or a
// shipped scene file), a measurement taken through tb::Simulation samples
// after every step, the analytic answer with its formula, and for each engine
// the value the figure is held against and the tolerance, with where that
// tolerance comes from.
//
// The same definitions drive the GoogleTest executable (validation_tests,
// which asserts them) and the report (validation_report, which writes
// docs/validation.md with both engines' figures side by side).
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "simulation.hpp"

namespace val {

constexpr double kNone = std::numeric_limits<double>::quiet_NaN();

/// What one engine's figure is held against.
struct Check {
    /// The value the figure must match: the analytic answer, or the exact
    /// answer of the engine's own discrete scheme where the case asks for that
    /// (free fall: the semi-implicit Euler recurrence). NaN: same as analytic.
    double reference = kNone;
    /// |figure − reference| ≤ tolerance.
    double tolerance = 0.0;
    /// Where the tolerance comes from (discretisation formula, rounding,
    /// compliance of a soft constraint, ...).
    std::string why;
    /// False: the figure is reported, not asserted (the issue asks only for
    /// part of the comparison in Box2D, e.g. the impact law's own cases).
    bool asserted = true;
    /// A known shortfall of the engine: the figure misses `tolerance` for the
    /// reason given here. The test then holds it to `issueTolerance` (the
    /// bound the stated cause allows), so that it cannot get worse unnoticed,
    /// and the report marks it ✗ against `tolerance`.
    std::string knownIssue;
    double issueTolerance = kNone;
};

struct Case {
    std::string id;        ///< test name, [a-z0-9_]
    std::string group;     ///< heading in the report
    std::string quantity;  ///< what is measured, with the unit
    std::string formula;   ///< the analytic answer's formula (empty when none)
    double analytic = kNone;
    /// Runs the case in one engine and returns the figure.
    std::function<double(tb::EngineKind)> measure;
    Check impulse2d;
    Check box2d;
    /// Why the two engines' figures differ, shown when they do.
    std::string whyTheyDiffer;

    const Check& check(tb::EngineKind kind) const { return kind == tb::EngineKind::box2d ? box2d : impulse2d; }
    double reference(tb::EngineKind kind) const {
        double r = check(kind).reference;
        return r == r ? r : analytic;
    }
};

/// Every case, in report order. `assetsDir` locates the shipped scenes.
std::vector<Case> allCases(const std::string& assetsDir);

/// The joint cases (joint_cases.cpp), in report order; scenes built in code.
std::vector<Case> jointCases();

/// Free fall for 1 s in Impulse2D with one substep and in Box2D 2.4.1: the
/// largest difference over the 60 steps between y_Impulse2D − y_Box2D and
/// g·h·t/2 (m). Box2D's semi-implicit Euler falls ahead of the parabola by
/// g·h·t/2 and Impulse2D's velocity Verlet falls on it, so this is rounding
/// only.
double oneSubstepFreeFallLead();

/// Complete elliptic integral of the first kind K(k) by the arithmetic-
/// geometric mean: K = π / (2 AGM(1, √(1 − k²))).
double ellipticK(double k);

}  // namespace val
