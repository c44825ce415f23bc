// A cluster of ranks that are threads of one process, for the tests: each rank's messages in a
// queue, and the films' sum made by the last rank to arrive.
#pragma once

#include <condition_variable>
#include <deque>
#include <mutex>
#include <vector>

#include "glint/cluster/transport.h"

namespace glint::testing {

class ThreadCluster {
public:
    explicit ThreadCluster(int ranks) : inboxes_(std::size_t(ranks)), arrays_(std::size_t(ranks)) {}

    class Rank : public Transport {
    public:
        Rank(ThreadCluster& cluster, int rank) : cluster_(cluster), rank_(rank) {}
        int rank() const override { return rank_; }
        int ranks() const override { return int(cluster_.inboxes_.size()); }
        void send(int to, const std::string& bytes) override {
            const std::lock_guard lock(cluster_.mutex_);
            cluster_.inboxes_[std::size_t(to)].push_back({rank_, bytes});
            cluster_.changed_.notify_all();
        }
        std::optional<Message> receive(std::chrono::milliseconds wait) override {
            std::unique_lock lock(cluster_.mutex_);
            auto& inbox = cluster_.inboxes_[std::size_t(rank_)];
            if (!cluster_.changed_.wait_for(lock, wait, [&] { return !inbox.empty(); }))
                return std::nullopt;
            Message m = std::move(inbox.front());
            inbox.pop_front();
            return m;
        }
        void sum_to_root(std::span<FixedSum> sums) override {
            std::unique_lock lock(cluster_.mutex_);
            const int generation = cluster_.generation_;
            cluster_.arrays_[std::size_t(rank_)] = sums;
            if (++cluster_.arrived_ < ranks()) {
                cluster_.changed_.wait(lock, [&] { return cluster_.generation_ != generation; });
                return;
            }
            std::span<FixedSum> root = cluster_.arrays_[0];
            for (std::size_t r = 1; r < cluster_.arrays_.size(); ++r)
                for (std::size_t i = 0; i < root.size(); ++i) root[i] += cluster_.arrays_[r][i];
            cluster_.arrived_ = 0;
            ++cluster_.generation_;
            cluster_.changed_.notify_all();
        }

    private:
        ThreadCluster& cluster_;
        int rank_;
    };

private:
    std::mutex mutex_;
    std::condition_variable changed_;
    std::vector<std::deque<Message>> inboxes_;
    std::vector<std::span<FixedSum>> arrays_;
    int arrived_ = 0, generation_ = 0;
};

}  // namespace glint::testing
