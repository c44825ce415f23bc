// Point-to-point messages with one tag, probed for with a short sleep so that a waiting rank
// leaves its cores to the renderer; the reduction in pieces of at most a mebibyte of sums.
#include "mpi_transport.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <thread>
#include <vector>

#include "command_errors.h"
#include "glint/cluster/cluster_render.h"

namespace glint::cli {

namespace {

constexpr int kTag = 1;        // the cluster's messages
constexpr int kGatherTag = 2;  // the texts gathered at the start

std::vector<std::string>& hosts() {
    static std::vector<std::string> names;
    return names;
}

// MPI's reduction: adds `in` into `inout`. The buffers MPI hands over need not be aligned for
// 128-bit loads: copied through.
void add_fixed_sums(void* in, void* inout, int* length, MPI_Datatype*) {
    const auto* a = static_cast<const unsigned char*>(in);
    auto* b = static_cast<unsigned char*>(inout);
    for (int i = 0; i < *length; ++i) {
        FixedSum x, y;
        std::memcpy(&x, a + i * sizeof(FixedSum), sizeof x);
        std::memcpy(&y, b + i * sizeof(FixedSum), sizeof y);
        y += x;
        std::memcpy(b + i * sizeof(FixedSum), &y, sizeof y);
    }
}

// Rank 0: every rank's text, its own first, each rank waited for at most `timeout`, by
// messages of their own (a collective could not say which rank is missing). The others send
// theirs and get nothing.
std::vector<std::string> gather_text(const std::string& text,
                                     std::chrono::duration<double> timeout) {
    int ranks = 1, rank = 0;
    MPI_Comm_size(MPI_COMM_WORLD, &ranks);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (rank != 0) {
        MPI_Send(text.data(), int(text.size()), MPI_CHAR, 0, kGatherTag, MPI_COMM_WORLD);
        return {};
    }
    std::vector<std::string> texts = {text};
    for (int r = 1; r < ranks; ++r) {
        const auto start = std::chrono::steady_clock::now();
        for (;;) {
            int flag = 0;
            MPI_Status status;
            MPI_Iprobe(r, kGatherTag, MPI_COMM_WORLD, &flag, &status);
            if (flag) {
                int count = 0;
                MPI_Get_count(&status, MPI_CHAR, &count);
                std::string theirs(std::size_t(count), '\0');
                MPI_Recv(theirs.data(), count, MPI_CHAR, r, kGatherTag, MPI_COMM_WORLD,
                         MPI_STATUS_IGNORE);
                texts.push_back(std::move(theirs));
                break;
            }
            if (std::chrono::steady_clock::now() - start > timeout)
                throw ClusterError(describe_rank(r) + " has not answered for " +
                                   std::to_string(int(timeout.count())) +
                                   " s (--rank-timeout): it stopped, or its host is unreachable");
            std::this_thread::sleep_for(std::chrono::microseconds(200));
        }
    }
    return texts;
}

}  // namespace

MpiTransport::MpiTransport() {
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &ranks_);
    MPI_Type_contiguous(int(sizeof(FixedSum)), MPI_BYTE, &sum_type_);
    MPI_Type_commit(&sum_type_);
    MPI_Op_create(&add_fixed_sums, 1, &add_);
}

MpiTransport::~MpiTransport() {
    for (Outgoing& out : outgoing_) MPI_Wait(&out.request, MPI_STATUS_IGNORE);
    MPI_Op_free(&add_);
    MPI_Type_free(&sum_type_);
}

void MpiTransport::send(int to, const std::string& bytes) {
    // Not waited for: a blocking send of a large message spins until the other rank takes it,
    // taking a core from the renderers. The bytes are kept until MPI is done with them.
    reap_sends();
    Outgoing& out = outgoing_.emplace_back(Outgoing{bytes, MPI_REQUEST_NULL});
    MPI_Isend(out.bytes.data(), int(out.bytes.size()), MPI_BYTE, to, kTag, MPI_COMM_WORLD,
              &out.request);
}

void MpiTransport::reap_sends() {
    for (auto it = outgoing_.begin(); it != outgoing_.end();) {
        int done = 0;
        MPI_Test(&it->request, &done, MPI_STATUS_IGNORE);
        it = done ? outgoing_.erase(it) : std::next(it);
    }
}

std::optional<Message> MpiTransport::receive(std::chrono::milliseconds wait) {
    const auto deadline = std::chrono::steady_clock::now() + wait;
    std::chrono::microseconds pause(20);
    reap_sends();
    for (;;) {
        int flag = 0;
        MPI_Status status;
        MPI_Iprobe(MPI_ANY_SOURCE, kTag, MPI_COMM_WORLD, &flag, &status);
        if (flag) {
            int count = 0;
            MPI_Get_count(&status, MPI_BYTE, &count);
            Message message{status.MPI_SOURCE, std::string(std::size_t(count), '\0')};
            MPI_Recv(message.bytes.data(), count, MPI_BYTE, status.MPI_SOURCE, kTag, MPI_COMM_WORLD,
                     MPI_STATUS_IGNORE);
            return message;
        }
        if (std::chrono::steady_clock::now() >= deadline) return std::nullopt;
        // Sleeps from 20 us, doubling to 1 ms while nothing comes: a quick answer when messages
        // flow, and the cores left to the renderers when they do not.
        std::this_thread::sleep_for(pause);
        pause = std::min(2 * pause, std::chrono::microseconds(1000));
    }
}

void MpiTransport::sum_to_root(std::span<FixedSum> sums) {
    std::optional<Watchdog> watchdog;
    if (rank_ == 0) watchdog.emplace(sum_timeout_, "the sum of the films");
    if (rank_ == 0)
        MPI_Reduce(MPI_IN_PLACE, sums.data(), int(sums.size()), sum_type_, add_, 0, MPI_COMM_WORLD);
    else
        MPI_Reduce(sums.data(), nullptr, int(sums.size()), sum_type_, add_, 0, MPI_COMM_WORLD);
}

Watchdog::Watchdog(std::chrono::duration<double> timeout, std::string what)
    : thread_([this, timeout, what = std::move(what)] {
          std::unique_lock lock(mutex_);
          if (ended_.wait_for(lock, timeout, [&] { return done_; })) return;
          std::fprintf(stderr,
                       "glint-mpi: error: a rank has not joined %s for %.0f s (--rank-timeout): "
                       "it stopped, or its host is unreachable; ending the job\n",
                       what.c_str(), timeout.count());
          std::fflush(stderr);
          std::_Exit(kExitFailure);
      }) {}

Watchdog::~Watchdog() {
    {
        const std::lock_guard lock(mutex_);
        done_ = true;
    }
    ended_.notify_one();
    thread_.join();
}

std::string describe_rank(int rank) {
    const auto& names = hosts();
    if (rank >= 0 && std::size_t(rank) < names.size())
        return "rank " + std::to_string(rank) + " (" + names[std::size_t(rank)] + ")";
    return "rank " + std::to_string(rank);
}

std::string check_versions(const std::string& version, std::chrono::duration<double> timeout) {
    char host[256] = {};
    gethostname(host, sizeof host - 1);
    const std::vector<std::string> texts = gather_text(version + '\n' + host, timeout);
    hosts().clear();
    std::vector<std::string> versions;
    for (const std::string& text : texts) {
        const std::size_t newline = text.find('\n');
        versions.push_back(text.substr(0, newline));
        hosts().push_back(text.substr(newline + 1));
    }
    for (std::size_t r = 1; r < versions.size(); ++r)
        if (versions[r] != versions[0])
            return describe_rank(int(r)) + " runs glint " + versions[r] + ", rank 0 glint " +
                   versions[0] + ": every rank must run the same glint";
    return {};
}

int first_different(const std::string& text, std::chrono::duration<double> timeout) {
    const std::vector<std::string> texts = gather_text(text, timeout);
    for (std::size_t r = 1; r < texts.size(); ++r)
        if (texts[r] != texts[0]) return int(r);
    return -1;
}

}  // namespace glint::cli
