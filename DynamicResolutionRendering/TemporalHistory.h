// The temporal filters' state between frames, with one owner: the frame plan
// computes what a frame leaves (FramePlan::history, from State()); Begin
// takes it and Commit stores it once the frame's resolve is recorded. A new
// allocation restarts it (Reset); a camera cut under TAAU drops it (Invalidate).
#pragma once

#include "FramePlan.h"

namespace drr {

class TemporalHistory {
 public:
  const TemporalState& State() const { return m_State; }
  void Begin(const FramePlan& plan) { m_Next = plan.history; }
  void Commit() { m_State = m_Next; }
  // The targets were re-created: the pair restarts at 0 with nothing in it.
  void Reset() {
    m_State.current = 0;
    m_State.valid = false;
  }
  void Invalidate() { m_State.valid = false; }

 private:
  TemporalState m_State, m_Next;
};

}  // namespace drr
