// Where a worker is, readable by its parent without a message: one shared page (a memfd) per
// worker holding the component the current request is in. The worker writes it as it enters each
// component (no system call); the parent reads it only when a request ends abnormally (a crash,
// a timeout, a limit), to say which component did it. A message per change would wake the
// parent, and those wake-ups cost more than the compile's whole isolation otherwise does.
#ifndef KILN_WORKER_PHASE_BOARD_H_
#define KILN_WORKER_PHASE_BOARD_H_

#include <atomic>
#include <cstdint>
#include <string>

#include "kiln/result.h"
#include "worker/protocol.h"

namespace kiln::worker {

class PhaseBoard {
  public:
    PhaseBoard() = default;
    ~PhaseBoard();
    PhaseBoard(PhaseBoard&& other) noexcept;
    PhaseBoard& operator=(PhaseBoard&& other) noexcept;

    // The parent's side: a new board; an error (K0011) with the reason when it cannot be made.
    Status Create();
    // The worker's side: the board behind an inherited descriptor.
    bool Attach(int fd);

    int fd() const { return fd_; }
    bool ok() const { return slot_ != nullptr; }
    void Set(Component c) {
        if (slot_ != nullptr)
            slot_->store(uint8_t(c), std::memory_order_release);
    }
    Component Get() const;

  private:
    void Release();
    int fd_ = -1;
    std::atomic<uint8_t>* slot_ = nullptr;
};

}  // namespace kiln::worker

#endif  // KILN_WORKER_PHASE_BOARD_H_
