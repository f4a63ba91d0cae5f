// The lock a query holds while it calls the game's accept function
// (QueryFilter::accept): a callback that tries to change the world gets
// i2d::Error, and the lock is released however the query ends, an exception
// from the callback included. A query without an accept function costs
// nothing more.
#pragma once

#include "impulse2d/types.hpp"
#include "world_state.hpp"

namespace i2d::detail {

class QueryLock {
public:
    QueryLock(WorldState& w, const QueryFilter& f) : w_(w), was_(w.locked) {
        if (f.accept) w_.locked = true;
    }
    ~QueryLock() { w_.locked = was_; }
    QueryLock(const QueryLock&) = delete;
    QueryLock& operator=(const QueryLock&) = delete;

private:
    WorldState& w_;
    bool was_;
};

}  // namespace i2d::detail
