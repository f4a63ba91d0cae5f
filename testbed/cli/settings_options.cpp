// Testbed — world-settings overrides from the command line (see settings_options.hpp).
#include "cli/settings_options.hpp"

namespace tb {

const char* settingsOptionsHelp() {
    return "settings options (override the scene's world settings):\n"
           "  --velocity-iterations N   velocity iterations per step (baumgarte, split; soft_step has one\n"
           "                            solve and one relax pass per substep); Box2D's with --engine box2d\n"
           "  --position-iterations N   position iterations (split); Box2D's with --engine box2d\n"
           "  --substeps N              substeps per step (soft_step)\n"
           "  --correction MODE         soft_step | baumgarte | split\n"
           "  --impact MODEL            closed_form | velocity_bias\n"
           "  --sleep on|off            enable or disable sleeping\n"
           "  --manifold-reuse D        manifold reuse distance (m); 0 recomputes every manifold every step\n"
           "  --exact-joint-mass-ratio R  joint trees whose heaviest body is at least R times the lightest\n"
           "                            (or whose load would stretch their soft joints, docs/joints.md)\n"
           "                            are solved exactly (1: every tree; 1e30: none)\n"
           "  --exact-column-tilt on|off  solve the tilt and shear of columns' two-point contacts exactly\n"
           "                            (default on; docs/validation.md, \"Columns solved as one\")\n"
           "  --contact-hertz F         contact stiffness (Hz, soft_step; capped at a quarter of the substep rate)\n"
           "  --contact-damping-ratio Z contact damping ratio (soft_step); an overlap is pushed out at about\n"
           "                            2π·F/(2·Z) per second, so raising both keeps that push and stiffens the rest\n"
           "  --threads N               workers the Impulse2D world steps on (default 1; the results are\n"
           "                            bit-identical for any N); Box2D 2.4.1 runs on one\n";
}

void SettingsOverrides::applyTo(i2d::WorldSettings& s) const {
    if (velocityIterations) s.velocityIterations = *velocityIterations;
    if (positionIterations) s.positionIterations = *positionIterations;
    if (substeps) s.substeps = *substeps;
    if (correction) s.positionCorrection = *correction;
    if (impact) s.impactModel = *impact;
    if (sleep) s.enableSleep = *sleep;
    if (manifoldReuse) s.manifoldReuseDistance = *manifoldReuse;
    if (exactJointMassRatio) s.exactJointMassRatio = *exactJointMassRatio;
    if (exactColumnTilt) s.exactColumnTilt = *exactColumnTilt;
    if (contactHertz) s.contactHertz = *contactHertz;
    if (contactDampingRatio) s.contactDampingRatio = *contactDampingRatio;
}

void SettingsOverrides::applyTo(SceneDesc& desc) const {
    applyTo(desc.settings);
    if (threads) desc.threads = *threads;
}

Box2DSettings SettingsOverrides::box2dSettings() const {
    Box2DSettings b;
    if (velocityIterations) b.velocityIterations = *velocityIterations;
    if (positionIterations) b.positionIterations = *positionIterations;
    return b;
}

bool parseSettingsOption(ArgReader& r, SettingsOverrides& o) {
    if (r.is("--velocity-iterations")) {
        o.velocityIterations = static_cast<int>(r.integer(1, 1000));
    } else if (r.is("--position-iterations")) {
        o.positionIterations = static_cast<int>(r.integer(0, 1000));
    } else if (r.is("--substeps")) {
        o.substeps = static_cast<int>(r.integer(1, 1000));
    } else if (r.is("--correction")) {
        o.correction = r.choice<i2d::PositionCorrection>();
    } else if (r.is("--impact")) {
        o.impact = r.choice<i2d::ImpactModel>();
    } else if (r.is("--manifold-reuse")) {
        o.manifoldReuse = static_cast<float>(r.number(0.0, 10.0));
    } else if (r.is("--exact-joint-mass-ratio")) {
        o.exactJointMassRatio = static_cast<float>(r.number(1.0, 1.0e30));
    } else if (r.is("--exact-column-tilt")) {
        o.exactColumnTilt = r.onOff();
    } else if (r.is("--contact-hertz")) {
        o.contactHertz = static_cast<float>(r.number(0.0, 1.0e6));
    } else if (r.is("--contact-damping-ratio")) {
        o.contactDampingRatio = static_cast<float>(r.number(0.0, 1.0e6));
    } else if (r.is("--threads")) {
        o.threads = static_cast<int>(r.integer(1, 64));
    } else if (r.is("--sleep")) {
        o.sleep = r.onOff();
    } else {
        return false;
    }
    return true;
}

}  // namespace tb
