// The cluster's transport on MPI (cluster/transport.h): messages of bytes between ranks of
// MPI_COMM_WORLD, and the films summed at rank 0 by MPI_Reduce with an operation that adds
// 128-bit fixed-point sums exactly, along MPI's reduction tree.
#pragma once

#include <mpi.h>

#include <chrono>
#include <condition_variable>
#include <list>
#include <mutex>
#include <string>
#include <thread>

#include "glint/cluster/transport.h"

namespace glint::cli {

class MpiTransport : public Transport {
public:
    MpiTransport();  // after MPI_Init
    ~MpiTransport() override;
    MpiTransport(const MpiTransport&) = delete;
    MpiTransport& operator=(const MpiTransport&) = delete;

    int rank() const override { return rank_; }
    int ranks() const override { return ranks_; }
    void send(int to, const std::string& bytes) override;
    std::optional<Message> receive(std::chrono::milliseconds wait) override;
    // On rank 0, a sum that has not ended after the timeout (a rank stopped or its host is gone)
    // ends the job: the message, then exit, which makes mpirun end every rank.
    void sum_to_root(std::span<FixedSum> sums) override;
    void set_sum_timeout(std::chrono::duration<double> timeout) { sum_timeout_ = timeout; }

private:
    struct Outgoing {
        std::string bytes;
        MPI_Request request;
    };
    void reap_sends();  // forgets the sends MPI is done with

    int rank_ = 0, ranks_ = 1;
    std::list<Outgoing> outgoing_;  // sends in flight: a list, so that their bytes stay put
    MPI_Datatype sum_type_{};
    MPI_Op add_{};
    std::chrono::duration<double> sum_timeout_{300};
};

// While it lives on rank 0, a collective call that has not ended after `timeout` (a rank
// stopped, or its host is gone) ends the job: it says so, naming what waited, and exits, which
// makes mpirun end every rank. MPI itself would wait for ever.
class Watchdog {
public:
    Watchdog(std::chrono::duration<double> timeout, std::string what);
    ~Watchdog();
    Watchdog(const Watchdog&) = delete;
    Watchdog& operator=(const Watchdog&) = delete;

private:
    std::mutex mutex_;
    std::condition_variable ended_;
    bool done_ = false;
    std::thread thread_;
};

// "rank 2 (node7)": each rank's host, gathered at the start (rank 0 alone knows them).
std::string describe_rank(int rank);
// Every rank: gathers the ranks' hosts and glint versions at rank 0, and returns the refusal of a
// rank whose glint differs from rank 0's (on rank 0; empty elsewhere and when all agree). A rank
// that sends nothing within `timeout` is named in a ClusterError.
std::string check_versions(const std::string& version, std::chrono::duration<double> timeout);
// Every rank: gathers `text` at rank 0, and on rank 0 returns the first rank whose text differs
// from rank 0's, or -1; likewise.
int first_different(const std::string& text, std::chrono::duration<double> timeout);

}  // namespace glint::cli
