// How the ranks of a cluster talk: messages of bytes between two ranks, and the sum of every
// rank's array of film sums at rank 0. MPI carries them in glint-mpi (mpi_transport.h); threads
// of one process in the tests.
#pragma once

#include <chrono>
#include <optional>
#include <span>
#include <string>

#include "glint/render/film/film.h"

namespace glint {

struct Message {
    int from = 0;
    std::string bytes;
};

class Transport {
public:
    virtual ~Transport() = default;
    virtual int rank() const = 0;
    virtual int ranks() const = 0;
    virtual void send(int to, const std::string& bytes) = 0;
    // The next message to this rank, from any; none if none came within `wait`.
    virtual std::optional<Message> receive(std::chrono::milliseconds wait) = 0;
    // Collective: every rank gives an array of the same length, and rank 0's becomes the sum of
    // all of them.
    virtual void sum_to_root(std::span<FixedSum> sums) = 0;
};

}  // namespace glint
