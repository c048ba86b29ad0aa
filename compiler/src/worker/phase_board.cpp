#include "worker/phase_board.h"

#include <sys/mman.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <utility>

namespace kiln::worker {
namespace {

constexpr size_t kBoardBytes = 4096;

std::atomic<uint8_t>* Map(int fd) {
    void* p = mmap(nullptr, kBoardBytes, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
    return p == MAP_FAILED ? nullptr : static_cast<std::atomic<uint8_t>*>(p);
}

}  // namespace

PhaseBoard::~PhaseBoard() {
    Release();
}

PhaseBoard::PhaseBoard(PhaseBoard&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)), slot_(std::exchange(other.slot_, nullptr)) {}

PhaseBoard& PhaseBoard::operator=(PhaseBoard&& other) noexcept {
    if (this != &other) {
        Release();
        fd_ = std::exchange(other.fd_, -1);
        slot_ = std::exchange(other.slot_, nullptr);
    }
    return *this;
}

void PhaseBoard::Release() {
    if (slot_ != nullptr)
        munmap(slot_, kBoardBytes);
    if (fd_ >= 0)
        close(fd_);
    slot_ = nullptr;
    fd_ = -1;
}

Status PhaseBoard::Create() {
    Release();
    fd_ = memfd_create("kiln-worker-phase", MFD_CLOEXEC);
    if (fd_ < 0 || ftruncate(fd_, kBoardBytes) != 0 || (slot_ = Map(fd_)) == nullptr) {
        Error error{DiagCode::kWorkerUnavailable,
                    std::string("cannot make the worker's phase board: ") + std::strerror(errno)};
        Release();
        return error;
    }
    return {};
}

bool PhaseBoard::Attach(int fd) {
    Release();
    fd_ = fd;
    slot_ = Map(fd);
    return slot_ != nullptr;
}

Component PhaseBoard::Get() const {
    if (slot_ == nullptr)
        return Component::kNone;
    const uint8_t c = slot_->load(std::memory_order_acquire);
    return c <= uint8_t(Component::kKilnReduction) ? Component(c) : Component::kNone;
}

}  // namespace kiln::worker
