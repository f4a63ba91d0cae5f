// The impact stage of a step: contacts that close with a real approach speed
// are resolved by the closed-form impact law (impact_law.cpp; Baber (2011),
// A Correction To Brian Mirtich's Thesis "Impulse-based Dynamic Simulation
// of Rigid Body Systems", §5) before the iterative solver runs, which then
// only sees what remains (resting contact, joints) and adds no restitution of
// its own.
//
// Strategy (see docs/impacts.md):
//  * A manifold's impact point is the mean of its points that approach faster
//    than impactThreshold and would close their gap within this step; a box
//    landing flat is thus struck at its centre line, not corner by corner.
//    A moving body's contacts with static pieces of one flat floor (normals
//    within 0.8°) are struck together, as one manifold.
//  * Contacts are swept in slot order, Gauss-Seidel fashion, each resolved with
//    the current velocities; sweeps repeat while some contact still
//    approaches, up to kMaxSweeps; if one still does, a shock pass follows
//    (propagateShock). A later sweep only revisits contacts whose
//    bodies changed in the previous sweep. Each application is the exact
//    law for that pair and never adds kinetic energy, so neither does any
//    sequence of them; a chain of touching bodies (Newton's cradle) passes
//    momentum along within one sweep.
//  * A speculative contact (gap s > 0 at the step's start) hits at time t*
//    into the step. The law acts on the velocities the bodies really have at
//    t*, and the bodies are given the velocities and start positions with
//    which the solver's integration of the step ends where flight until t*
//    and rebound after it would (below, "Timing within the step").
#include <algorithm>
#include <cmath>

#include "contact.hpp"
#include "impact_look.hpp"
#include "impact_stage.hpp"
#include "impulse2d/impact.hpp"
#include "integration.hpp"
#include "split_kick.hpp"
#include "union_find.hpp"
#include "world_state.hpp"

namespace i2d::detail {

namespace {
constexpr int kMaxSweeps = 8;
/// What `changed` holds for a body struck by the shock pass.
constexpr std::uint32_t kShockStamp = kMaxSweeps + 1;
/// Passes over one level's contacts in the shock pass (a body held up by
/// two or more below it needs a few: each strike turns it about the point).
constexpr int kShockPasses = 8;
/// A moving body's static contacts struck with one of them (a face landing
/// across a floor's seams): those whose normals lie within 0.8° of its
/// (cos 0.8°, the seam rule's face alignment, seams.cpp), at most this many.
constexpr float kGroupAlignment = 0.9999f;
constexpr int kMaxGroupedContacts = 8;

// Timing within the step. The solver integrates by semi-implicit Euler over
// N substeps of h = Δt/N: v_k = v_(k−1) + a·h, x_k = x_(k−1) + h·v_k, with a
// a body's free acceleration (gravity, force). From a stored velocity v the
// positions then follow exactly the parabola x(t) = x0 + (v + a·h/2)·t +
// a·t²/2: the stored velocity is half a substep of acceleration away from the
// velocity the body really has, v_true = v + a·h/2 (the staggering of the
// symplectic Euler method; Hairer, Lubich and Wanner (2003), Geometric
// numerical integration illustrated by the Störmer–Verlet method, §1.2). The
// law is applied to the true velocities at the moment of impact t*,
//   v(t*) = v + a·(h/2 + t*),
// and gives true velocities v⁺ at t*. Storing
//   v_new = v⁺ − a·(t* + h/2)
// and moving the start of the step by
//   δ = t*·(v(t*) − v⁺)
// makes the solver's N substeps end at the exact position and (staggered)
// velocity of flight until t* and rebound after it (expand both and the terms
// in a·Δt², a·h·Δt cancel). Without the staggering, every rebound was launched
// a·h/2 too slow and the flight after it lost u·h/2 of apex height (u the
// rebound speed): −6.5 % at the third bounce of a ball with e = 0.5 dropped
// from 5 m, −61 % at the fourth. Rotation has no free acceleration here: its
// start is moved by t*·(ω before − ω after) as before.

/// What the law strikes on one side of a contact: a body, or the rigid
/// cluster of bodies welded to it (findWeldClusters), as one rigid body: the
/// bodies' summed mass, their common centre of mass, their summed inertia
/// about it (each body's own and m·|c − C|²), and the velocity and spin of
/// their summed momentum and angular momentum about that centre.
struct StruckSide {
    float invMass = 0.0f, invInertia = 0.0f;
    Vec2 center{}, v{}, acc{};
    float w = 0.0f;
    int cluster = -1;
};

/// Rigid welds (no spring) between two awake dynamic bodies join their bodies
/// into clusters that the impact stage strikes as one body. Struck one body at
/// a time, as if each were free, the light box of a pair welded to one 100
/// times as dense rebounded with its own mass, its start shifted to fly at that
/// rebound, and the weld took it back from there: of 200 such pairs dropped at
/// random angles, 13 gained more than 1 % of their energy at 4 substeps, the
/// worst thrown up with 2.2 times its start (docs/validation.md, energy audit).
void findWeldClusters(WorldState& w) {
    std::vector<int>& cluster = w.weldCluster;
    std::vector<int>& bodies = w.weldClusterBodies;
    for (int b : bodies) cluster[static_cast<std::size_t>(b)] = -1;
    bodies.clear();
    w.weldClusterStart.clear();
    if (w.joints.count == 0) return;
    if (cluster.size() < static_cast<std::size_t>(w.bodies.capacity()))
        cluster.resize(static_cast<std::size_t>(w.bodies.capacity()), -1);
    // Union-find over the welded bodies' places in `bodies` (parents in the scratch).
    std::vector<int>& parent = w.weldClusterScratch;
    parent.clear();
    auto find = [&](int i) { return unionFindRoot(parent, i); };
    auto place = [&](int b) {
        int& c = cluster[static_cast<std::size_t>(b)];
        if (c < 0) {
            c = static_cast<int>(bodies.size());
            bodies.push_back(b);
            parent.push_back(c);
        }
        return c;
    };
    auto struckAlone = [&](const Body& b) { return b.type != BodyType::dynamic_body || !b.awake || !b.enabled; };
    for (int j = 0; j < w.joints.capacity(); ++j) {
        const Joint& joint = w.joints[j];
        if (!joint.alive || joint.type != JointType::weld || joint.bodyA == joint.bodyB) continue;
        const WeldJointDef& def = std::get<WeldJointDef>(joint.def);
        if (def.linearHertz != 0.0f || def.angularHertz != 0.0f) continue;
        if (struckAlone(w.bodies[joint.bodyA]) || struckAlone(w.bodies[joint.bodyB])) continue;
        const int a = find(place(joint.bodyA)), b = find(place(joint.bodyB));
        if (a != b) parent[static_cast<std::size_t>(a)] = b;
    }
    if (bodies.empty()) return;
    // Clusters numbered by their roots' first places (each place's number in
    // `number`), then the bodies grouped by cluster (counted in `start`,
    // placed with `number` reused as the write cursors).
    const std::size_t n = bodies.size();
    std::vector<int>& number = w.weldClusterNumber;
    std::vector<int>& start = w.weldClusterStart;
    std::vector<int>& grouped = w.weldClusterGrouped;
    grouped.resize(n);
    for (std::size_t i = 0; i < n; ++i) grouped[i] = find(static_cast<int>(i));  // (roots, before parent is reused)
    number.assign(n, -1);
    start.assign(1, 0);
    for (std::size_t i = 0; i < n; ++i) {
        int& k = number[static_cast<std::size_t>(grouped[i])];
        if (k < 0) {
            k = static_cast<int>(start.size()) - 1;
            start.push_back(0);
        }
        ++start[static_cast<std::size_t>(k) + 1];
        parent[i] = k;  // (now each place's cluster)
    }
    for (std::size_t k = 1; k < start.size(); ++k) start[k] += start[k - 1];
    for (std::size_t k = 0; k + 1 < start.size(); ++k) number[k] = start[k];
    for (std::size_t i = 0; i < n; ++i)
        grouped[static_cast<std::size_t>(number[static_cast<std::size_t>(parent[i])]++)] = bodies[i];
    bodies.swap(grouped);
    for (std::size_t k = 0; k + 1 < start.size(); ++k)
        for (int i = start[k]; i < start[k + 1]; ++i)
            cluster[static_cast<std::size_t>(bodies[static_cast<std::size_t>(i)])] = static_cast<int>(k);
}

/// The first time t in [0, dt] at which a gap s closing at speed vn < 0 with
/// acceleration an (along the normal) reaches zero: s + vn·t + an·t²/2 = 0;
/// dt if it does not close within the step.
float closingTime(float s, float vn, float an, float dt) {
    if (s <= 0.0f) return 0.0f;
    if (std::abs(an) < 1e-6f) return vn < 0.0f ? std::min(s / -vn, dt) : dt;
    const float disc = vn * vn - 2.0f * an * s;
    if (disc < 0.0f) return dt;
    // The smaller positive root, in the form that keeps precision for small an.
    const float t = 2.0f * s / (-vn + std::sqrt(disc));
    return t > 0.0f ? std::min(t, dt) : dt;
}

/// Shock propagation (Guendelman, Bridson and Fedkiw (2003), Nonconvex rigid
/// bodies with stacking, where it is a pass of the contact solver): when the
/// sweeps end with contacts still approaching, or a heavy body closes on a
/// light one (kShockMassRatio), the bodies are ranked by how many contacts
/// lie between them and something that cannot move (level 0: static,
/// kinematic and sleeping bodies; level k + 1: touching a body of level k),
/// and the approaching
/// contacts are struck level by level from the bottom up, each body of the
/// level below held immovable for the law. A 400 kg box landing on two 1 kg
/// boxes on the ground is stopped by the ground in one pass, where each
/// pairwise sweep took only a 400th of its approach and let it drive the
/// light boxes 0.5 m into the ground (docs/impacts.md, "Shock
/// propagation"). The held body takes no impulse, so the momentum the
/// sweeps could not carry down goes into the ground; a pass that would end
/// with more kinetic energy than it started with (a held body moving up into
/// the one above it) is undone.
template <class Strike>
void propagateShock(WorldState& w, Strike&& strike, float threshold, float residual) {
    std::vector<ShockEdge>& edges = w.shockEdges;
    std::vector<int>& local = w.shockLocal;    // body slot -> index in `graph`, -1
    std::vector<int>& graph = w.shockBodies;   // the bodies of the contacts below
    std::vector<int>& level = w.shockLevel;    // per index in `graph`, -1 unreached
    std::vector<int>& offset = w.shockOffset;  // adjacency (compressed rows)
    std::vector<int>& adjacent = w.shockAdjacent;
    edges.clear();
    graph.clear();
    w.shockSaved.clear();
    if (local.size() < static_cast<std::size_t>(w.bodies.capacity()))
        local.resize(static_cast<std::size_t>(w.bodies.capacity()), -1);
    auto moves = [&](const Body& b) { return b.type == BodyType::dynamic_body && b.awake; };
    auto indexOf = [&](int b) {
        int& i = local[static_cast<std::size_t>(b)];
        if (i < 0) {
            i = static_cast<int>(graph.size());
            graph.push_back(b);
        }
        return i;
    };
    // The touching contacts with points, from the narrowphase's look
    // (kLookRow), without reading the contacts.
    for (std::size_t i = 0; i < w.activeContacts.size(); ++i) {
        const ContactLook& look = w.activeLooks[i];
        if ((look.rowFlags & kLookRow) == 0) continue;
        if (!moves(w.bodies[look.bodyA]) && !moves(w.bodies[look.bodyB])) continue;
        const bool heavy = (look.rowFlags & kLookHeavyOnLight) != 0;
        edges.push_back({w.activeContacts[i], indexOf(look.bodyA), indexOf(look.bodyB), 0, heavy});
    }
    const std::size_t n = graph.size();
    offset.assign(n + 1, 0);
    for (const ShockEdge& e : edges) {
        ++offset[static_cast<std::size_t>(e.a) + 1];
        ++offset[static_cast<std::size_t>(e.b) + 1];
    }
    for (std::size_t i = 0; i < n; ++i) offset[i + 1] += offset[i];
    adjacent.resize(2 * edges.size());
    {
        std::vector<int>& fill = w.shockFill;
        fill.assign(offset.begin(), offset.end() - 1);
        for (const ShockEdge& e : edges) {
            adjacent[static_cast<std::size_t>(fill[static_cast<std::size_t>(e.a)]++)] = e.b;
            adjacent[static_cast<std::size_t>(fill[static_cast<std::size_t>(e.b)]++)] = e.a;
        }
    }
    // Levels, breadth first from the bodies that cannot move (the queue is
    // `fill`, reused).
    level.assign(n, -1);
    std::vector<int>& queue = w.shockFill;
    queue.clear();
    for (std::size_t i = 0; i < n; ++i)
        if (!moves(w.bodies[graph[i]])) {
            level[i] = 0;
            queue.push_back(static_cast<int>(i));
        }
    for (std::size_t head = 0; head < queue.size(); ++head) {
        const auto i = static_cast<std::size_t>(queue[head]);
        for (int k = offset[i]; k < offset[i + 1]; ++k) {
            const auto j = static_cast<std::size_t>(adjacent[static_cast<std::size_t>(k)]);
            if (level[j] < 0) {
                level[j] = level[i] + 1;
                queue.push_back(static_cast<int>(j));
            }
        }
    }
    for (int b : graph) local[static_cast<std::size_t>(b)] = -1;

    // A contact belongs to the level of its upper body. Contacts of bodies
    // nothing holds up (a pile in the air) keep what the sweeps left: their
    // momentum has nowhere to go.
    std::size_t kept = 0;
    for (const ShockEdge& e : edges) {
        const int la = level[static_cast<std::size_t>(e.a)], lb = level[static_cast<std::size_t>(e.b)];
        if (la < 0 || lb < 0) continue;
        edges[kept++] = {e.contact, la, lb, std::max(la, lb), e.heavyOnLight};
    }
    edges.resize(kept);
    std::stable_sort(edges.begin(), edges.end(),
                     [](const ShockEdge& x, const ShockEdge& y) { return x.level < y.level; });
    for (std::size_t first = 0; first < edges.size();) {
        std::size_t last = first;
        while (last < edges.size() && edges[last].level == edges[first].level) ++last;
        for (int pass = 0; pass < kShockPasses; ++pass) {
            bool any = false;
            for (std::size_t i = first; i < last; ++i) {
                const ShockEdge& e = edges[i];  // a, b: the bodies' levels here
                // Only where the sweeps or this pass changed a body, or a
                // heavy body closes on a light one: elsewhere nothing
                // approaches.
                const Contact& ct = w.contacts[e.contact];
                const std::uint32_t changedA = w.impactChanged[static_cast<std::size_t>(ct.bodyA)];
                const std::uint32_t changedB = w.impactChanged[static_cast<std::size_t>(ct.bodyB)];
                if (changedA == 0u && changedB == 0u && !e.heavyOnLight) continue;
                // Struck down to the residual only where this pass has
                // struck a body already or a heavy body closes on a light
                // one; elsewhere only impacts (resting contacts keep their
                // warm start, and a column of equal boxes that the sweeps
                // nearly settled is not turned).
                const bool struck = changedA == kShockStamp || changedB == kShockStamp || e.heavyOnLight;
                if (strike(e.contact, e.a < e.b, e.b < e.a, struck ? residual : threshold)) any = true;
            }
            if (!any) break;
        }
        first = last;
    }

    // Undone if it gained kinetic energy (above).
    double before = 0.0, after = 0.0;
    for (const ShockSaved& saved : w.shockSaved) {
        const Body& now = w.bodies[saved.body];
        before += now.mass * dot(saved.v, saved.v) + now.inertia * saved.w * saved.w;
        after += now.mass * dot(now.v, now.v) + now.inertia * now.w * now.w;
    }
    if (after > before)
        for (const ShockSaved& saved : w.shockSaved) {
            Body& now = w.bodies[saved.body];
            now.v = saved.v;
            now.w = saved.w;
            now.center = saved.center;
            now.xf = saved.xf;
        }
    w.shockSaved.clear();
}

}  // namespace

void resolveImpacts(WorldState& w, float dt) {
    // changed[b] == the sweep in which body b's velocity last changed (0:
    // none this step). hitTime[c] == when contact c was struck in this step,
    // −1 while it was not; bodyTime[b] the same for body b's earliest
    // impact, and bodyDv[b], bodyDw[b] its change of velocity so far.
    // Kept between steps and only grown: the entries the last stage wrote
    // (its struck bodies and contacts) go back to their defaults here, so a
    // step pays for what was struck, not for every slot (filled anew every
    // step, they charged 10,000 idle bodies to the 100 awake beside them).
    // Sized at a world's first strike: until then every entry would hold its
    // default (nothing struck), and a world that never strikes anything
    // holds none of them (20 bytes a body slot, 4 a contact slot).
    std::vector<std::uint32_t>& changed = w.impactChanged;
    std::vector<float>& hitTime = w.impactTime;
    std::vector<float>& bodyTime = w.impactBodyTime;
    std::vector<Vec2>& bodyDv = w.impactBodyDv;
    std::vector<float>& bodyDw = w.impactBodyDw;
    for (int b : w.impactStruckBodies) {
        changed[static_cast<std::size_t>(b)] = 0u;
        bodyTime[static_cast<std::size_t>(b)] = -1.0f;
    }
    for (int c : w.impactStruckContacts) hitTime[static_cast<std::size_t>(c)] = -1.0f;
    w.impactStruckBodies.clear();
    w.impactStruckContacts.clear();
    bool sized = false;
    auto sizeArrays = [&] {
        if (sized) return;
        sized = true;
        const auto bodySlots = static_cast<std::size_t>(w.bodies.capacity());
        const auto contactSlots = static_cast<std::size_t>(w.contacts.capacity());
        if (changed.size() < bodySlots) changed.resize(bodySlots, 0u);
        if (bodyTime.size() < bodySlots) {
            bodyTime.resize(bodySlots, -1.0f);
            bodyDv.resize(bodySlots);
            bodyDw.resize(bodySlots);
            w.impactStarts.resize(bodySlots);
        }
        if (hitTime.size() < contactSlots) hitTime.resize(contactSlots, -1.0f);
    };

    const WorldSettings& settings = w.settings;
    if (settings.impactModel != ImpactModel::closed_form) return;
    const float threshold = settings.impactThreshold;
    const int substeps = solverSubsteps(settings);
    const float halfSubstep = 0.5f * dt / static_cast<float>(substeps);
    // The speeds the step integrates with (clampVelocity): a strike's change
    // beyond them is never flown. Shifted by the whole of it, a 2.4e-26 kg
    // body struck to 1e24 m/s had its start moved 1.8e22 m and its rotation
    // turned to NaN (fuzz_world).
    const float maxSpeed = settings.maxLinearSpeed;
    const float maxAngularSpeed = kMaxRotationPerStep / (2.0f * halfSubstep);

    std::uint32_t sweepStamp = 0;
    // Moves body b's start so that the step ends as flight until its
    // earliest impact and its whole change of velocity after it (timing
    // above; "Cascades" in docs/impacts.md). This strike's change (dv, dw)
    // is moved by that time, and when the strike is earlier than any before
    // it, the changes before it are moved back to it too.
    auto shiftStart = [&](Body& body, int b, float tHit, Vec2 dv, float dw) {
        const auto i = static_cast<std::size_t>(b);
        float& earliest = bodyTime[i];
        if (earliest < 0.0f) {
            earliest = tHit;
            bodyDv[i] = {};
            bodyDw[i] = 0.0f;
        }
        const float t = std::min(earliest, tHit);
        const Vec2 move = t * dv + (t - earliest) * bodyDv[i];
        const float turn = t * dw + (t - earliest) * bodyDw[i];
        earliest = t;
        bodyDv[i] += dv;
        bodyDw[i] += dw;
        if (move.x == 0.0f && move.y == 0.0f && turn == 0.0f) return;
        StepStart& start = w.impactStarts[i];
        if (start.stamp != w.stepStamp) start = {body.center, body.xf.q, w.stepStamp};
        w.startsShiftedAt = w.stepStamp;
        body.center += move;
        body.xf.q = integrateRotation(body.xf.q, turn);
        body.xf.p = body.center - rotate(body.xf.q, body.localCenter);
    };

    // The first sweep's look at each contact was taken by the narrowphase
    // (passesOverImpacts), from the bodies' motion at the stage's start. That is
    // the look the sweep itself would take while neither body has been struck
    // (a strike marks both in `changed`); for a contact with a struck body the
    // sweep looks again. (Taken here, on the workers in a pass of its own, it
    // read every contact and both its bodies once more: 4 to 6 % of the step
    // of a large pile. The bodies' motion was once copied into an array by
    // body slot for it: filled every step, it made 10,000 idle bodies cost the
    // 100 awake beside them a fifth more.)
    const std::size_t activeCount = w.activeContacts.size();
    const std::vector<ContactLook>& looks = w.activeLooks;
    auto passedOver = [&](const Contact& ct) { return passesOverImpacts(w, ct, ct.touching); };
    auto stillPassedOver = [&](std::size_t i) {  // in the first sweep
        const ContactLook& l = looks[i];
        // (Before the first strike no body is marked, and the arrays may be unsized.)
        return l.passOver && (w.impactStruckBodies.empty() || (changed[static_cast<std::size_t>(l.bodyA)] != 1u &&
                                                               changed[static_cast<std::size_t>(l.bodyB)] != 1u));
    };

    // Rigid clusters of welded bodies, struck as one body (findWeldClusters),
    // found at the step's first strike: most steps strike nothing.
    bool clustersFound = false;
    auto struckSide = [&](int body, bool moves) {
        if (!clustersFound) {
            findWeldClusters(w);
            clustersFound = true;
        }
        StruckSide side;
        const int k = body < static_cast<int>(w.weldCluster.size()) ? w.weldCluster[static_cast<std::size_t>(body)]
                                                                    : -1;
        // A body whose forces were split holds its true velocity: made the
        // lagging one the timing above reads (split_kick.hpp). Struck, it
        // has a contact row this step and keeps that meaning.
        if (k < 0) {
            Body& b = w.bodies[body];
            if (moves) makeVelocityLag(b, settings.gravity, halfSubstep, maxSpeed, maxAngularSpeed);
            return StruckSide{b.invMass, b.invInertia, b.center, b.v, freeAcceleration(b, moves, settings.gravity), b.w,
                              -1};
        }
        side.cluster = k;
        const int first = w.weldClusterStart[static_cast<std::size_t>(k)];
        const int last = w.weldClusterStart[static_cast<std::size_t>(k) + 1];
        double mass = 0.0, cx = 0.0, cy = 0.0, px = 0.0, py = 0.0, fx = 0.0, fy = 0.0;
        bool turns = true;
        for (int i = first; i < last; ++i) {
            Body& b = w.bodies[w.weldClusterBodies[static_cast<std::size_t>(i)]];
            makeVelocityLag(b, settings.gravity, halfSubstep, maxSpeed, maxAngularSpeed);
            const Vec2 a = freeAcceleration(b, true, settings.gravity);
            mass += b.mass;
            cx += double(b.mass) * b.center.x, cy += double(b.mass) * b.center.y;
            px += double(b.mass) * b.v.x, py += double(b.mass) * b.v.y;
            fx += double(b.mass) * a.x, fy += double(b.mass) * a.y;
            turns = turns && b.invInertia > 0.0f;
        }
        if (!(mass > 0.0)) return side;  // (massless: nothing to strike)
        side.center = {static_cast<float>(cx / mass), static_cast<float>(cy / mass)};
        side.v = {static_cast<float>(px / mass), static_cast<float>(py / mass)};
        side.acc = {static_cast<float>(fx / mass), static_cast<float>(fy / mass)};
        side.invMass = static_cast<float>(1.0 / mass);
        // Angular momentum and inertia about the common centre.
        double momentum = 0.0, inertia = 0.0;
        for (int i = first; i < last; ++i) {
            const Body& b = w.bodies[w.weldClusterBodies[static_cast<std::size_t>(i)]];
            const double rx = double(b.center.x) - side.center.x, ry = double(b.center.y) - side.center.y;
            momentum += double(b.inertia) * b.w + double(b.mass) * (rx * b.v.y - ry * b.v.x);
            inertia += double(b.inertia) + double(b.mass) * (rx * rx + ry * ry);
        }
        side.invInertia = turns && inertia > 0.0 ? static_cast<float>(1.0 / inertia) : 0.0f;
        side.w = inertia > 0.0 ? static_cast<float>(momentum / inertia) : 0.0f;
        return side;
    };
    // Calls f for the body, or for every body of its cluster.
    auto forEachStruck = [&](int body, const StruckSide& side, auto&& f) {
        if (side.cluster < 0) return f(body);
        const int first = w.weldClusterStart[static_cast<std::size_t>(side.cluster)];
        const int last = w.weldClusterStart[static_cast<std::size_t>(side.cluster) + 1];
        for (int i = first; i < last; ++i) f(w.weldClusterBodies[static_cast<std::size_t>(i)]);
    };

    // Strikes contact c with the law, its current velocities and its first
    // moment of impact; `holdA`/`holdB` make that body immovable for the law
    // (shock propagation, below) while its velocity still counts. False when
    // the contact does not approach or the law finds no collision.
    auto strike = [&](int c, bool holdA, bool holdB, float minApproach) {
        Contact& ct = w.contacts[c];
        if (minApproach == threshold && passedOver(ct)) return false;
        if (ct.overlapFromStart) return false;  // not an impact (passesOverImpacts)
        Body& A = w.bodies[ct.bodyA];
        Body& B = w.bodies[ct.bodyB];
        if (A.type != BodyType::dynamic_body && B.type != BodyType::dynamic_body) return false;
        if (!A.awake && !B.awake) return false;
        const Vec2 n = ct.manifold.normal;  // from A to B
        const bool aMoves = A.type == BodyType::dynamic_body && A.awake;
        const bool bMoves = B.type == BodyType::dynamic_body && B.awake;
        const bool aTakes = aMoves && !holdA;
        const bool bTakes = bMoves && !holdB;
        if (!aTakes && !bTakes) return false;
        const StruckSide sideA = struckSide(ct.bodyA, aMoves), sideB = struckSide(ct.bodyB, bMoves);
        if (sideA.cluster >= 0 && sideA.cluster == sideB.cluster) return false;  // (within one rigid cluster)
        const Vec2 accA = sideA.acc, accB = sideB.acc;
        const float an = dot(accB - accA, n);  // relative normal acceleration
        Vec2 point{};
        float gap = 0.0f, approach = 0.0f;
        int count = 0;
        // In the shock pass a contact struck before in this step met then:
        // it closes. (The sweeps keep to the start's gap: striking such a
        // pair again in every sweep made a landing column of 50 boxes sway
        // 0.23 m instead of 0.03 m.)
        const bool met = sweepStamp == kShockStamp && hitTime[static_cast<std::size_t>(c)] >= 0.0f;
        auto gather = [&](const Manifold& m) {
            int found = 0;
            for (int j = 0; j < m.pointCount; ++j) {
                const ManifoldPoint& mp = m.points[j];
                Vec2 dv = (sideB.v + cross(sideB.w, mp.point - sideB.center)) -
                          (sideA.v + cross(sideA.w, mp.point - sideA.center));
                float vn = dot(dv, n);
                // Closes within the step along its true flight (timing above),
                // faster than minApproach when it meets: a gap's approach
                // after its flight (impactThreshold is a speed at impact:
                // judged at the step's start instead, a ball with e = 0.5
                // landing at 1.16 m/s, 0.99 m/s when the step began, did not
                // bounce), a point already touching (or a pair met before in
                // this step) as it is.
                const float vTrue = vn + an * halfSubstep;
                const bool closes = met || mp.separation + (vTrue + 0.5f * an * dt) * dt < 0.0f;
                const float vMeet = met || !(mp.separation > 0.0f)
                                        ? vn
                                        : vTrue + an * closingTime(mp.separation, vTrue, an, dt);
                if (closes && vMeet < -minApproach) {
                    point += mp.point;
                    gap += std::max(mp.separation, 0.0f);
                    approach += vn;
                    ++found;
                }
            }
            return found;
        };
        count = gather(ct.manifold);
        if (count == 0) return false;
        // A face landing on a floor of several static pieces (a chain's
        // segments, tiles) touches each piece through its own contact, but
        // meets one flat surface: struck contact by contact, a box landing
        // flat across a seam was struck at each piece's points in turn, off
        // its centre, and spun (at 5 rad/s from 5 m). The static contacts of
        // the moving body whose normals are this one's are struck with it,
        // at the mean of all their approaching points, as one manifold.
        int grouped[kMaxGroupedContacts];
        int groupedCount = 0;
        const bool aFixed = A.type == BodyType::static_body, bFixed = B.type == BodyType::static_body;
        if (aFixed != bFixed && sweepStamp != kShockStamp && sideA.cluster < 0 && sideB.cluster < 0) {
            const int mover = aFixed ? ct.bodyB : ct.bodyA;
            const Vec2 up = aFixed ? n : -n;  // from the floor to the moving body
            for (const int c2 : w.bodies[mover].contacts) {
                if (c2 == c || groupedCount == kMaxGroupedContacts) continue;
                const Contact& o = w.contacts[c2];
                if (!o.touching || o.isSensor || o.overlapFromStart || o.manifold.pointCount == 0) continue;
                const bool oFixedA = o.bodyA != mover;
                if (w.bodies[oFixedA ? o.bodyA : o.bodyB].type != BodyType::static_body) continue;
                if (dot(oFixedA ? o.manifold.normal : -o.manifold.normal, up) < kGroupAlignment) continue;
                if (minApproach == threshold && passedOver(o)) continue;
                // (Its approaching points, if any, join the sums here.)
                const int found = gather(o.manifold);
                if (found > 0) {
                    grouped[groupedCount++] = c2;
                    count += found;
                }
            }
        }
        sizeArrays();
        const float inv = 1.0f / static_cast<float>(count);
        point = inv * point;
        gap *= inv;
        approach *= inv;

        // Time of impact within the step and the velocities then (timing above).
        // A pair struck again in a later sweep (a body of it was struck by
        // a third meanwhile) is struck at the moment it first met: its gap
        // closed then. Timed again from the start's gap at the new, slower
        // approach, each repeat moved the pair's start positions by about
        // the gap again, into each other, where its rows (keeping the
        // start's gap) could not see it.
        float& firstHit = hitTime[static_cast<std::size_t>(c)];
        if (firstHit < 0.0f) w.impactStruckContacts.push_back(c);
        // A contact whose points were found only after a body of it was
        // struck (refreshStruckContacts) closes from that strike on: timed
        // from the step's start at the new approach, a body struck late in
        // the step was hit early by its neighbour, and its start moved back
        // by the difference times its whole change of velocity (a box in a
        // drum turning at 12 rad/s, shifted so, went through the drum).
        float from = 0.0f;
        if (ct.foundAfterStrike)
            from = std::max(
                {0.0f, bodyTime[static_cast<std::size_t>(ct.bodyA)], bodyTime[static_cast<std::size_t>(ct.bodyB)]});
        const float tHit = firstHit >= 0.0f
                               ? firstHit
                               : std::min(from + closingTime(gap, approach + an * halfSubstep, an, dt), dt);
        firstHit = tHit;
        // The velocities at the hit, within the speed limit the solver's
        // integration holds them to: a body of 2.4e-26 kg under an applied
        // force has a free acceleration beyond 1e25 m/s², and taken whole it
        // reached the law at 7e25 m/s, whose change moved its start 1e24 m
        // (fuzz_world; continuous collision then met a non-finite normal).
        const Vec2 vA0 = limitSpeed(sideA.v + (halfSubstep + tHit) * accA, maxSpeed);
        const Vec2 vB0 = limitSpeed(sideB.v + (halfSubstep + tHit) * accB, maxSpeed);
        const float wB0 = sideB.w, wA0 = sideA.w;

        // The law's convention: f points from B to A and A receives +p.
        // Our manifold normal points from A to B, so A of the law is our B.
        ImpactInput in;
        // The shock pass's strikes below the impact threshold are what the
        // solver would have taken, without restitution.
        in.restitution = -(gap > 0.0f ? approach + an * (halfSubstep + tHit) : approach) < threshold ? 0.0f
                                                                                                     : ct.restitution;
        in.friction = sweepStamp == kShockStamp ? 0.0f : ct.friction;
        in.normal = {n.x, n.y};
        Vec2 rB = point - sideB.center, rA = point - sideA.center;
        // A body the shock pass holds is immovable for the law, and stops
        // the other's approach as the ground would. Moving towards the
        // other at the point, it would also drive the other away at its own
        // speed, taking nothing back: it is struck as still along the normal
        // there, and what it closes is left to the solver's rows.
        auto heldStill = [&](Vec2 v, float spin, Vec2 r, float towards) {
            const float u = towards * dot(v + cross(spin, r), n);
            return u > 0.0f ? v - (towards * u) * n : v;
        };
        const Vec2 vLawA = holdA ? heldStill(vA0, wA0, rA, 1.0f) : vA0;
        const Vec2 vLawB = holdB ? heldStill(vB0, wB0, rB, -1.0f) : vB0;
        in.a = {bTakes ? sideB.invMass : 0.0, bTakes ? sideB.invInertia : 0.0, {rB.x, rB.y}, {vLawB.x, vLawB.y}, wB0};
        in.b = {aTakes ? sideA.invMass : 0.0, aTakes ? sideA.invInertia : 0.0, {rA.x, rA.y}, {vLawA.x, vLawA.y}, wA0};
        ImpactResult r;
        try {
            r = resolveImpact(in);
        } catch (const Error&) {
            return false;  // e.g. two immovable bodies: nothing to resolve
        }
        if (r.kind == ImpactCase::not_colliding) return false;

        auto markStruck = [&](int b) {
            std::uint32_t& when = changed[static_cast<std::size_t>(b)];
            if (when == 0u) w.impactStruckBodies.push_back(b);
            // The shock pass keeps what it struck, to undo it (below).
            if (sweepStamp == kShockStamp && when != kShockStamp) {
                const Body& body = w.bodies[b];
                w.shockSaved.push_back({b, body.v, body.w, body.center, body.xf});
            }
            when = sweepStamp;
        };
        forEachStruck(ct.bodyA, sideA, markStruck);
        forEachStruck(ct.bodyB, sideB, markStruck);
        const Vec2 vBAfter = limitSpeed({static_cast<float>(r.vA.x), static_cast<float>(r.vA.y)}, maxSpeed);
        const Vec2 vAAfter = limitSpeed({static_cast<float>(r.vB.x), static_cast<float>(r.vB.y)}, maxSpeed);
        auto limitTurn = [&](double spin) {
            return static_cast<float>(std::clamp(spin, -double(maxAngularSpeed), double(maxAngularSpeed)));
        };
        // Each body's velocity changes at its earliest impact of the step
        // (shiftStart); a cluster's bodies each by the cluster's rigid
        // change at their centres.
        auto take = [&](int body, const StruckSide& side, Vec2 v0, Vec2 vAfter, float w0, float wAfter) {
            if (side.cluster < 0) {
                Body& struck = w.bodies[body];
                struck.v = vAfter - (tHit + halfSubstep) * side.acc;
                struck.w = wAfter;
                shiftStart(struck, body, tHit, v0 - vAfter, w0 - wAfter);
                return;
            }
            const Vec2 dv = vAfter - v0;
            const float dw = wAfter - w0;
            forEachStruck(body, side, [&](int b) {
                Body& struck = w.bodies[b];
                const Vec2 v = struck.v;
                const float spin = struck.w;
                struck.v = limitSpeed(v + dv + cross(dw, struck.center - side.center), maxSpeed);
                struck.w = limitTurn(double(spin) + dw);
                shiftStart(struck, b, tHit, v - struck.v, spin - struck.w);
            });
        };
        if (bTakes) take(ct.bodyB, sideB, vB0, vBAfter, wB0, limitTurn(r.wA));
        if (aTakes) take(ct.bodyA, sideA, vA0, vAAfter, wA0, limitTurn(r.wB));
        // The solver must not undo the bounce with stale warm-start impulses.
        // A strike below the impact threshold (the shock pass's) stops a
        // closing the solver would have taken: the contact's load stays.
        if (-approach >= threshold) {
            ct.normalImpulse[0] = ct.normalImpulse[1] = 0.0f;
            ct.tangentImpulse[0] = ct.tangentImpulse[1] = 0.0f;
        }
        for (int g = 0; g < groupedCount; ++g) {
            const int c2 = grouped[g];
            float& hit = hitTime[static_cast<std::size_t>(c2)];
            if (hit < 0.0f) {
                w.impactStruckContacts.push_back(c2);
                hit = tHit;
            }
            if (-approach >= threshold) {
                Contact& o = w.contacts[c2];
                o.normalImpulse[0] = o.normalImpulse[1] = 0.0f;
                o.tangentImpulse[0] = o.tangentImpulse[1] = 0.0f;
            }
        }
        // The manifold keeps its start-of-step gap: the rows add what the
        // shifts above opened or closed, less a struck pair's rebound since
        // t*, which is flight, not overlap (contact_row.hpp, impactShift).
        return true;
    };

    // The contacts of the bodies the sweep (or shock pass) of `stamp` struck
    // computed again at their new velocities (refreshStruckContacts).
    auto refreshStruckAt = [&](std::uint32_t stamp) {
        std::vector<int>& fresh = w.impactFreshlyStruck;
        fresh.clear();
        for (const int b : w.impactStruckBodies)
            if (changed[static_cast<std::size_t>(b)] == stamp) fresh.push_back(b);
        refreshStruckContacts(w, fresh);
    };

    // A heavy body closing on a light one (the narrowphase's look) calls
    // for the shock pass whatever the sweeps do; found in the first sweep.
    bool heavyOnLight = false;
    bool settled = false;
    for (int sweep = 1; sweep <= kMaxSweeps; ++sweep) {
        bool any = false;
        sweepStamp = static_cast<std::uint32_t>(sweep);
        for (std::size_t i = 0; i < activeCount; ++i) {
            if (sweep == 1) {
                heavyOnLight = heavyOnLight || (looks[i].rowFlags & kLookHeavyOnLight) != 0;
                if (stillPassedOver(i)) continue;
            }
            // A later sweep looks only at the contacts of bodies the last one
            // struck, found from the narrowphase's look (its bodies) before the
            // contact is read: in a large pile the later sweeps read every
            // contact and both its bodies to pass over nearly all of them.
            if (sweep > 1 && changed[static_cast<std::size_t>(looks[i].bodyA)] != sweepStamp - 1 &&
                changed[static_cast<std::size_t>(looks[i].bodyB)] != sweepStamp - 1)
                continue;
            if (strike(w.activeContacts[i], false, false, threshold)) any = true;
        }
        if (!any) {
            settled = true;
            break;
        }
        // A body this sweep struck may now reach a neighbour it had no
        // manifold point with: such contacts get their points, which the next
        // sweep (it looks at this sweep's bodies' contacts) strikes. Struck
        // in the solver instead, as rows without restitution, a row of
        // elastic balls 5 cm apart passed on half the energy.
        refreshStruckAt(sweepStamp);
    }
    if (!settled || heavyOnLight) {
        sweepStamp = kShockStamp;
        sizeArrays();
        propagateShock(w, strike, threshold, kShockResidual * threshold);
        refreshStruckAt(kShockStamp);  // what the shock pass struck: rows for the solver
    }
}

}  // namespace i2d::detail
