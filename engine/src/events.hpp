// Events: the lists a World reports after each step, and the lists of end
// events caused between steps, which wait for the next step.
//
// The lists a caller reads (contactBegin … sensorEnd, contactHit) change only
// inside step(): whatever the caller does between two steps — destroying
// bodies or shapes, changing filters, body types or joints — goes to the
// pending lists, so a span handed out stays valid and unchanged until the
// next step() begins. That step first clears the reported lists and moves the
// pending end events into them, ahead of the step's own events, so every end
// event is reported exactly once and after its begin.
#pragma once

#include <vector>

#include "impulse2d/types.hpp"

namespace i2d::detail {

struct EventBuffers {
    // Reported: the events of the last step.
    std::vector<ContactBeginEvent> contactBegin;
    std::vector<ContactEndEvent> contactEnd;
    std::vector<ContactHitEvent> contactHit;
    std::vector<SensorBeginEvent> sensorBegin;
    std::vector<SensorEndEvent> sensorEnd;
    // Caused between steps: reported with the next step.
    std::vector<ContactEndEvent> pendingContactEnd;
    std::vector<SensorEndEvent> pendingSensorEnd;

    /// Where an end event goes: the step's list while stepping, the pending
    /// list between steps.
    std::vector<ContactEndEvent>& contactEndList(bool stepping) { return stepping ? contactEnd : pendingContactEnd; }
    std::vector<SensorEndEvent>& sensorEndList(bool stepping) { return stepping ? sensorEnd : pendingSensorEnd; }

    /// Called when a step begins: drops the last step's events and moves the
    /// end events caused since into the lists of this step.
    void beginStep() {
        contactBegin.clear();
        contactHit.clear();
        sensorBegin.clear();
        contactEnd.swap(pendingContactEnd);
        pendingContactEnd.clear();
        sensorEnd.swap(pendingSensorEnd);
        pendingSensorEnd.clear();
        // A burst of events (a level built at once begins every contact)
        // does not hold its storage for the rest of the run.
        releaseIfLarge(contactBegin);
        releaseIfLarge(contactHit);
        releaseIfLarge(sensorBegin);
        releaseIfLarge(pendingContactEnd);
        releaseIfLarge(pendingSensorEnd);
    }

private:
    template <class T>
    static void releaseIfLarge(std::vector<T>& v) {
        if (v.capacity() * sizeof(T) > 64 * 1024) std::vector<T>().swap(v);
    }
};

}  // namespace i2d::detail
