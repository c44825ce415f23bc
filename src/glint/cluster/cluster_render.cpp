// The root's loop: answer each rank that asks (take its results, hand it ready pieces), keep the
// local renderer thread fed, watch every rank that holds work against the timeout, and at each
// pass boundary that wants a checkpoint, and at the end, let every rank go idle and sum the films.
#include "glint/cluster/cluster_render.h"

#include <tbb/info.h>

#include <algorithm>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "glint/cluster/work_dispatch.h"
#include "glint/render/byte_stream.h"
#include "glint/render/counts_codec.h"
#include "glint/render/state_sums.h"
#include "glint/render/tile_carry.h"
#include "glint/render/tiles.h"

namespace glint {

namespace {

using Clock = std::chrono::steady_clock;

// The first byte of every message.
enum class Kind : std::uint8_t {
    ask = 1,   // to rank 0: the results of the pieces held, and room for more
    work = 2,  // from rank 0: pieces with their tiles' carries
    sum = 3,   // from rank 0: sum the films now, then ask again or (1 follows) end
};

// The sums a collective call adds at most: 16 MiB of them.
constexpr std::size_t kSumPiece = std::size_t(1) << 20;

// Pieces a rank asks for at a time: two for each of its threads, so that none waits for the
// last tile of a batch alone.
int capacity_of(const RenderOptions& options) {
    return 2 * (options.threads > 0 ? options.threads : tbb::info::default_concurrency());
}

// The options a renderer of pieces runs with: the hooks are the root's to call, once.
RenderOptions renderer_options(const RenderOptions& options, IntegratorCache& cache,
                               std::mutex* state_mutex) {
    RenderOptions local = options;
    local.after_pass = {};
    local.after_tile = {};
    local.after_piece = {};
    local.state_mutex = state_mutex;
    local.integrator_cache = &cache;
    return local;
}

// Sums every rank's films at rank 0, piece by piece; with `reset`, the other ranks' own sums
// become zero, as rank 0 now holds them.
void sum_films(Transport& transport, RenderState& state, bool reset) {
    const std::size_t n = sum_count(state);
    std::vector<FixedSum> piece(std::min(n, kSumPiece));
    for (std::size_t first = 0; first < n; first += kSumPiece) {
        const std::span<FixedSum> sums(piece.data(), std::min(kSumPiece, n - first));
        copy_sums(state, first, sums);
        transport.sum_to_root(sums);
        if (transport.rank() == 0) {
            write_sums(state, first, sums);
        } else if (reset) {
            std::fill(sums.begin(), sums.end(), FixedSum(0));
            write_sums(state, first, sums);
        }
    }
}

std::string ask_message(int capacity, const std::vector<WorkPiece>& done, const RenderState& state,
                        const std::vector<Tile>& tiles) {
    ByteWriter out;
    out.u8(std::uint8_t(Kind::ask));
    out.i32(capacity);
    out.u32(std::uint32_t(done.size()));
    for (const WorkPiece& piece : done) {
        out.i32(piece.pass);
        out.i32(piece.tile);
        write_carry(out, take_carry(state, tiles[std::size_t(piece.tile)], piece.tile));
    }
    write_counts(out, state.rays, state.bad_samples);
    return std::move(out.bytes());
}

std::string work_message(const std::vector<WorkPiece>& pieces, const RenderState& state,
                         const std::vector<Tile>& tiles) {
    ByteWriter out;
    out.u8(std::uint8_t(Kind::work));
    out.u32(std::uint32_t(pieces.size()));
    for (const WorkPiece& piece : pieces) {
        out.i32(piece.pass);
        out.i32(piece.tile);
        write_carry(out, take_carry(state, tiles[std::size_t(piece.tile)], piece.tile));
    }
    return std::move(out.bytes());
}

std::string sum_message(bool then_end) {
    ByteWriter out;
    out.u8(std::uint8_t(Kind::sum));
    out.u8(then_end ? 1 : 0);
    return std::move(out.bytes());
}

// A piece named in a message: a tile of the render.
WorkPiece read_piece(ByteReader<>& in, std::size_t tiles) {
    WorkPiece piece;
    piece.pass = in.i32();
    piece.tile = in.i32();
    if (piece.tile < 0 || std::size_t(piece.tile) >= tiles || piece.pass < 0)
        throw std::runtime_error("a message names a piece outside the render");
    return piece;
}

// Rank 0's view of another rank.
struct Peer {
    bool waiting = false;  // it asked, and has had no answer
    int capacity = 0;
    std::vector<WorkPiece> held;  // the pieces it is rendering
    Clock::time_point since;      // when it was last answered (or the job began)
};

// The renderer on rank 0's own thread: takes pieces while the root lets it, renders them into
// the root's state.
class LocalRenderer {
public:
    LocalRenderer(const World& world, const RenderOptions& options, RenderState& state,
                  WorkDispatch& dispatch, std::mutex& book, std::mutex& state_mutex)
        : world_(world),
          options_(renderer_options(options, cache_, &state_mutex)),
          capacity_(capacity_of(options)),
          state_(state),
          dispatch_(dispatch),
          book_(book),
          thread_([this] { run(); }) {}
    ~LocalRenderer() { end(); }

    // Under the book's lock: let it take work, or hold it back (a checkpoint, a stop).
    void allow(bool allowed) {
        allowed_ = allowed;
        wake_.notify_one();
    }
    void wake() { wake_.notify_one(); }
    // Under the book's lock.
    bool busy() const { return busy_; }
    std::vector<WorkPiece> take_finished() { return std::exchange(finished_, {}); }
    std::exception_ptr error() const { return error_; }

    // Waits for the batch in flight, and ends the thread.
    void end() {
        {
            const std::lock_guard lock(book_);
            over_ = true;
            wake_.notify_one();
        }
        if (thread_.joinable()) thread_.join();
    }

private:
    void run() {
        for (;;) {
            std::vector<WorkPiece> pieces;
            {
                std::unique_lock lock(book_);
                wake_.wait(lock, [&] {
                    if (over_ || error_) return true;
                    if (allowed_) pieces = dispatch_.take(capacity_);
                    return !pieces.empty();
                });
                if (pieces.empty()) return;
                busy_ = true;
            }
            try {
                render_pieces(world_, options_, state_, pieces);
            } catch (...) {
                const std::lock_guard lock(book_);
                error_ = std::current_exception();
                dispatch_.give_back(pieces);
                busy_ = false;
                return;
            }
            const std::lock_guard lock(book_);
            for (const WorkPiece& piece : pieces) dispatch_.finish(piece);
            finished_.insert(finished_.end(), pieces.begin(), pieces.end());
            busy_ = false;
        }
    }

    const World& world_;
    IntegratorCache cache_;
    const RenderOptions options_;
    const int capacity_;
    RenderState& state_;
    WorkDispatch& dispatch_;
    std::mutex& book_;  // guards the dispatch and the fields below
    std::condition_variable wake_;
    bool allowed_ = true, over_ = false, busy_ = false;
    std::vector<WorkPiece> finished_;
    std::exception_ptr error_;
    std::thread thread_;  // last: it starts once the rest is set
};

}  // namespace

RenderResult render_as_root(const World& world, const RenderOptions& options, Transport& transport,
                            RenderState& state, const ClusterOptions& cluster,
                            RenderProgress* progress) {
    const auto start = Clock::now();
    const double seconds_before = state.seconds;
    const RenderSettings& settings = world.settings();
    const std::vector<Tile> tiles = make_tiles(settings.width, settings.height, options.tile_size);
    const int passes = pass_count(settings.samples_per_pixel, state.pass_size);
    if (state.tile_passes.size() != tiles.size())
        throw std::invalid_argument("render_as_root: the state is of another tile size");
    const auto name = [&](int rank) {
        return cluster.describe_rank ? cluster.describe_rank(rank) : "rank " + std::to_string(rank);
    };

    WorkDispatch dispatch(state.tile_passes, passes);
    std::mutex book, own_state_mutex;
    std::mutex& state_mutex = options.state_mutex ? *options.state_mutex : own_state_mutex;
    if (progress) {
        progress->tiles_done = 0;
        progress->passes_done = dispatch.passes_done();
        progress->passes_total = passes;
        progress->tiles_total = dispatch.left();
    }
    std::vector<Peer> peers(std::size_t(transport.ranks()));
    for (Peer& peer : peers) peer.since = start;
    int passes_done = dispatch.passes_done();
    // From here on the dispatch is the book's lock's: the local renderer takes from it.
    LocalRenderer local(world, options, state, dispatch, book, state_mutex);
    bool stopping = false, checkpoint_due = false;

    const auto all_idle = [&] {  // under the book's lock
        for (std::size_t r = 1; r < peers.size(); ++r)
            if (!peers[r].waiting) return false;
        return !local.busy();
    };
    ClusterStats own_stats;
    ClusterStats& stats = cluster.stats ? *cluster.stats : own_stats;
    stats.pieces.assign(peers.size(), 0);
    const auto report = [&](const std::vector<WorkPiece>& finished) {
        for (const WorkPiece& piece : finished) {
            if (progress) ++progress->tiles_done;
            if (options.after_piece) options.after_piece(piece.pass, piece.tile);
        }
    };
    // Every rank idle: sums the films, every other rank told to first.
    const auto sum_all = [&](bool then_end) {
        for (std::size_t r = 1; r < peers.size(); ++r) {
            transport.send(int(r), sum_message(then_end));
            peers[r].waiting = false;
            peers[r].since = Clock::now();
        }
        const auto sum_start = Clock::now();
        sum_films(transport, state, false);
        ++stats.sums;
        stats.sum_seconds += std::chrono::duration<double>(Clock::now() - sum_start).count();
    };

    // A rank's answer: the carries and counts of the pieces it held; then it waits for more.
    const auto take_answer = [&](const Message& message) {
        const int r = message.from;
        stats.bytes += message.bytes.size();
        if (r <= 0 || r >= int(peers.size()) || peers[std::size_t(r)].waiting)
            throw ClusterError("a message came from " + name(r) + " out of turn");
        Peer& peer = peers[std::size_t(r)];
        try {
            ByteReader<> in(reinterpret_cast<const unsigned char*>(message.bytes.data()),
                            message.bytes.size(), "a message was cut short");
            if (in.u8() != std::uint8_t(Kind::ask)) throw std::runtime_error("not a request");
            peer.capacity = std::clamp(in.i32(), 1, 1 << 16);
            const std::uint32_t n = in.u32();
            if (n != peer.held.size())
                throw std::runtime_error("results of pieces it was not given");
            std::vector<WorkPiece> finished;
            for (std::uint32_t i = 0; i < n; ++i) {
                const WorkPiece piece = read_piece(in, tiles.size());
                if (std::find(peer.held.begin(), peer.held.end(), piece) == peer.held.end())
                    throw std::runtime_error("results of pieces it was not given");
                const Tile& tile = tiles[std::size_t(piece.tile)];
                const TileCarry carry = read_carry(in, state, tile);
                const std::lock_guard lock(state_mutex);
                put_carry(state, tile, carry);
                state.tile_passes[std::size_t(piece.tile)] = piece.pass + 1;
                finished.push_back(piece);
            }
            RayStats rays;
            BadSamples bad;
            read_counts(in, rays, bad);
            {
                const std::lock_guard lock(state_mutex);
                state.rays += rays;
                state.bad_samples += bad;
            }
            {
                const std::lock_guard lock(book);
                for (const WorkPiece& piece : finished) dispatch.finish(piece);
                local.wake();
            }
            report(finished);
            stats.pieces[std::size_t(r)] += int(finished.size());
        } catch (const std::runtime_error& e) {
            throw ClusterError("a message from " + name(r) + " makes no sense: " + e.what());
        }
        peer.held.clear();
        peer.waiting = true;
    };
    // Pieces to each waiting rank, as many as it asked for; under the book's lock.
    const auto hand_out = [&] {
        for (std::size_t r = 1; r < peers.size(); ++r) {
            Peer& peer = peers[r];
            if (!peer.waiting) continue;
            std::vector<WorkPiece> pieces = dispatch.take(peer.capacity);
            if (pieces.empty()) break;
            std::string bytes;
            {
                const std::lock_guard state_lock(state_mutex);
                bytes = work_message(pieces, state, tiles);
            }
            transport.send(int(r), bytes);
            stats.bytes += bytes.size();
            peer.held = std::move(pieces);
            peer.waiting = false;
            peer.since = Clock::now();
        }
    };
    // A rank that holds work and has not answered within the timeout ends the render.
    const auto check_answers_come = [&] {
        const auto now = Clock::now();
        for (std::size_t r = 1; r < peers.size(); ++r)
            if (!peers[r].waiting && now - peers[r].since > cluster.rank_timeout)
                throw ClusterError(
                    name(int(r)) + " has not answered for " +
                    std::to_string(
                        int(std::chrono::duration<double>(now - peers[r].since).count())) +
                    " s (the limit is " +
                    std::to_string(
                        int(std::chrono::duration<double>(cluster.rank_timeout).count())) +
                    " s): it stopped, or its host is unreachable");
    };

    for (;;) {
        if (const std::exception_ptr error = [&] {
                const std::lock_guard lock(book);
                return local.error();
            }())
            std::rethrow_exception(error);
        if (progress && (progress->cancel || progress->stop_after_pass) && !stopping) {
            const std::lock_guard lock(book);
            stopping = true;
            local.allow(false);
        }
        if (const std::optional<Message> message = transport.receive(std::chrono::milliseconds(2)))
            take_answer(*message);
        std::unique_lock lock(book);
        const std::vector<WorkPiece> finished = local.take_finished();
        const int now_done = dispatch.passes_done();
        const bool done = dispatch.done();
        lock.unlock();
        report(finished);
        stats.pieces[0] += int(finished.size());
        if (progress) progress->passes_done = now_done;
        if (now_done > passes_done) {
            passes_done = now_done;
            // As render() does: after each pass but the last, not after a stop.
            if (options.after_pass && now_done < passes && !stopping) checkpoint_due = true;
        }
        lock.lock();
        if (checkpoint_due) local.allow(false);
        const bool idle = all_idle();
        if ((done || stopping) && idle) break;
        if (checkpoint_due && idle) {
            lock.unlock();
            sum_all(false);
            options.after_pass(state);
            lock.lock();
            checkpoint_due = false;
            local.allow(!stopping);
        }
        if (!checkpoint_due && !stopping) hand_out();
        lock.unlock();
        check_answers_come();
    }
    local.end();
    if (const std::exception_ptr error = local.error()) std::rethrow_exception(error);
    sum_all(true);
    RenderResult result = render_result(state, options);
    state.seconds = seconds_before + std::chrono::duration<double>(Clock::now() - start).count();
    result.seconds = state.seconds;
    result.complete = dispatch.done();
    return result;
}

RenderEngine cluster_engine(Transport& transport, ClusterOptions cluster) {
    return [&transport, cluster = std::move(cluster)](
               const World& world, const RenderOptions& options, RenderProgress& progress,
               RenderState& state, std::span<const WorkPiece> work) {
        if (!work.empty())
            throw std::invalid_argument("a render across ranks takes all that is left");
        return render_as_root(world, options, transport, state, cluster, &progress);
    };
}

void render_as_worker(const World& world, const RenderOptions& options, Transport& transport) {
    const RenderSettings& settings = world.settings();
    const std::vector<Tile> tiles = make_tiles(settings.width, settings.height, options.tile_size);
    RenderState scratch = initial_state(settings, options);
    IntegratorCache cache;
    const RenderOptions local = renderer_options(options, cache, nullptr);
    const int capacity = capacity_of(options);
    transport.send(0, ask_message(capacity, {}, scratch, tiles));
    for (;;) {
        const std::optional<Message> message = transport.receive(std::chrono::milliseconds(1000));
        if (!message) continue;
        if (message->from != 0) throw ClusterError("a message came from a rank other than 0");
        ByteReader<> in(reinterpret_cast<const unsigned char*>(message->bytes.data()),
                        message->bytes.size(), "a message from rank 0 was cut short");
        const std::uint8_t kind = in.u8();
        scratch.rays = RayStats{};
        scratch.bad_samples = BadSamples{};
        std::vector<WorkPiece> pieces;
        if (kind == std::uint8_t(Kind::sum)) {
            const bool then_end = in.u8() != 0;
            sum_films(transport, scratch, true);
            if (then_end) return;
        } else if (kind == std::uint8_t(Kind::work)) {
            const std::uint32_t n = in.u32();
            for (std::uint32_t i = 0; i < n; ++i) {
                const WorkPiece piece = read_piece(in, tiles.size());
                const Tile& tile = tiles[std::size_t(piece.tile)];
                put_carry(scratch, tile, read_carry(in, scratch, tile));
                scratch.tile_passes[std::size_t(piece.tile)] = piece.pass;
                pieces.push_back(piece);
            }
            render_pieces(world, local, scratch, pieces);
        } else {
            throw ClusterError("rank 0 sent a message of an unknown kind");
        }
        transport.send(0, ask_message(capacity, pieces, scratch, tiles));
    }
}

}  // namespace glint
