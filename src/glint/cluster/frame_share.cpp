// Every rank keeps one frame renderer, a thread that renders a frame at a time; the main thread
// alone sends and receives, as MPI's funnelled threading asks. Rank 0's main thread also writes
// what comes back.
#include "glint/cluster/frame_share.h"

#include <algorithm>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <mutex>
#include <string>
#include <thread>
#include <utility>

#include "glint/render/byte_stream.h"
#include "glint/render/state_transfer.h"

namespace glint {

namespace {

using Clock = std::chrono::steady_clock;

// The first byte of every message of the frames' protocol; apart from the tiles' (1 to 3).
enum class FrameMessage : std::uint8_t {
    frame = 11,       // to a rank: a frame to render, and its saved state if it has one
    stop = 12,        // to a rank: stop the frame (1 follows: at once; 0: after its pass)
    over = 13,        // to a rank: no more frames
    alive = 14,       // to rank 0: still rendering the frame
    checkpoint = 15,  // to rank 0: the frame's state so far
    done = 16,        // to rank 0: the frame's state, and whether every pass was done
};

std::string frame_message(int frame, const std::string& text, const RenderState* saved,
                          int tile_size) {
    ByteWriter out;
    out.u8(std::uint8_t(FrameMessage::frame));
    out.i32(frame);
    out.text(text);
    out.u8(saved ? 1 : 0);
    if (saved) write_state(out, *saved, tile_size);
    return std::move(out.bytes());
}

std::string encoded(const RenderState& state, int tile_size) {
    ByteWriter out;
    write_state(out, state, tile_size);
    return std::move(out.bytes());
}

// A frame's state, `encoded`, after the kind and the frame.
std::string state_message(FrameMessage kind, int frame, const std::string& state,
                          bool complete = false) {
    ByteWriter out;
    out.u8(std::uint8_t(kind));
    out.i32(frame);
    out.u8(complete ? 1 : 0);
    return std::move(out.bytes()) + state;
}

std::string short_message(FrameMessage kind, int value) {
    ByteWriter out;
    out.u8(std::uint8_t(kind));
    out.i32(value);
    return std::move(out.bytes());
}

ByteReader<> reader_of(const Message& message) {
    return ByteReader<>(reinterpret_cast<const unsigned char*>(message.bytes.data()),
                        message.bytes.size(), "a message was cut short");
}

// A thread that renders one frame at a time, from a fresh state or one given.
class FrameRenderer {
public:
    // Fills a fresh state of the frame's render with the one it continues from.
    using Load = std::function<void(RenderState& state)>;
    struct Checkpoint {
        int frame;
        std::string state;  // encoded: a state is not copied
    };
    struct Done {
        int frame;
        bool complete;
        RenderState state;
    };

    explicit FrameRenderer(const FrameRendering& rendering) : rendering_(rendering) {}
    ~FrameRenderer() {
        stop(true);
        if (thread_.joinable()) thread_.join();
    }

    // From start() until its frame is taken as done.
    bool busy() const {
        const std::lock_guard lock(mutex_);
        return busy_;
    }
    int frame() const { return frame_; }  // the last begun

    // Renders `frame`; with `text`, refuses to when the frame's own text (FrameRendering::text)
    // is another.
    void start(int frame, Load load, std::optional<std::string> text = std::nullopt) {
        if (thread_.joinable()) thread_.join();
        progress_.stop_after_pass = false;
        progress_.cancel = false;
        frame_ = frame;
        {
            const std::lock_guard lock(mutex_);
            busy_ = true;
        }
        thread_ = std::thread([this, frame, load = std::move(load), text = std::move(text)] {
            run(frame, load, text);
        });
    }
    void stop(bool at_once) {
        progress_.stop_after_pass = true;
        if (at_once) progress_.cancel = true;
    }

    std::optional<Checkpoint> take_checkpoint() {
        const std::lock_guard lock(mutex_);
        return std::exchange(checkpoint_, std::nullopt);
    }
    // The frame done; a checkpoint of it not yet taken is dropped, as the frame's end has passed
    // it.
    std::optional<Done> take_done() {
        const std::lock_guard lock(mutex_);
        if (done_) {
            busy_ = false;
            checkpoint_.reset();
        }
        return std::exchange(done_, std::nullopt);
    }
    std::exception_ptr error() const {
        const std::lock_guard lock(mutex_);
        return error_;
    }

private:
    void run(int frame, const Load& load, const std::optional<std::string>& text) {
        try {
            FrameSetup setup = rendering_.set_up(frame);
            if (setup.options.tile_size != rendering_.tile_size)
                throw std::logic_error("a frame set up with another tile size");
            if (text && rendering_.text && rendering_.text(*setup.world, setup.options) != *text)
                throw ClusterError("this rank made another render of frame " +
                                   std::to_string(frame) +
                                   " than rank 0 (another glint build, or other options): every "
                                   "rank must be given the same command");
            RenderState state = initial_state(setup.world->settings(), setup.options);
            if (load) load(state);
            if (rendering_.checkpoint_every)
                setup.options.after_pass =
                    [this, frame, last = Clock::now()](const RenderState& so_far) mutable {
                        if (Clock::now() - last < *rendering_.checkpoint_every) return;
                        last = Clock::now();
                        std::string bytes = encoded(so_far, rendering_.tile_size);
                        const std::lock_guard lock(mutex_);
                        checkpoint_.emplace(Checkpoint{frame, std::move(bytes)});
                    };
            std::function<void(int)> hold;
            if (rendering_.hold) hold = rendering_.hold(progress_);
            std::atomic<int> pieces{0};
            if (hold) setup.options.after_piece = [&](int, int) { hold(++pieces); };
            const RenderResult result = render(*setup.world, setup.options, &progress_, &state);
            const std::lock_guard lock(mutex_);
            done_.emplace(Done{frame, result.complete, std::move(state)});
        } catch (...) {
            const std::lock_guard lock(mutex_);
            error_ = std::current_exception();
        }
    }

    const FrameRendering& rendering_;
    RenderProgress progress_;
    mutable std::mutex mutex_;  // guards the fields below
    bool busy_ = false;
    std::optional<Checkpoint> checkpoint_;
    std::optional<Done> done_;
    std::exception_ptr error_;
    int frame_ = -1;
    std::thread thread_;
};

}  // namespace

bool share_frames_as_root(Transport& transport, const std::vector<int>& frames,
                          const FrameRendering& rendering, const FrameBook& book,
                          const ClusterOptions& cluster, RenderProgress& progress,
                          std::vector<int>* frames_by_rank) {
    const auto name = [&](int rank) {
        return cluster.describe_rank ? cluster.describe_rank(rank) : "rank " + std::to_string(rank);
    };
    const int ranks = transport.ranks();
    std::deque<int> queue(frames.begin(), frames.end());
    // Each other rank's frame (-1: none) and when it was last heard from.
    struct Holder {
        int frame = -1;
        Clock::time_point heard;
    };
    std::vector<Holder> held(static_cast<std::size_t>(ranks));
    std::vector<int> by_rank(std::size_t(ranks), 0);
    FrameRenderer local(rendering);
    bool stopping = false, at_once = false, all_complete = true;

    const auto finish = [&](int frame, int rank, const RenderState& state, bool complete) {
        book.finished(frame, rank, state, complete);
        all_complete = all_complete && complete;
        if (complete) ++by_rank[std::size_t(rank)];
    };
    const auto hand_out = [&](int rank) {
        const int frame = queue.front();
        queue.pop_front();
        std::optional<RenderState> saved = book.saved(frame);
        if (rank == 0) {
            auto kept = std::make_shared<std::optional<RenderState>>(std::move(saved));
            local.start(frame, [kept](RenderState& state) {
                if (*kept) state = std::move(**kept);
            });
            return;
        }
        transport.send(rank, frame_message(frame, book.text ? book.text(frame) : std::string(),
                                           saved ? &*saved : nullptr, rendering.tile_size));
        held[std::size_t(rank)] = {frame, Clock::now()};
    };
    const auto stop_all = [&](bool now) {
        local.stop(now);
        for (int r = 1; r < ranks; ++r)
            if (held[std::size_t(r)].frame >= 0)
                transport.send(r, short_message(FrameMessage::stop, now));
    };
    // A message from a rank that holds a frame: it is alive, at a checkpoint, or done.
    const auto take_message = [&](const Message& message) {
        const int r = message.from;
        if (r <= 0 || r >= ranks || held[std::size_t(r)].frame < 0)
            throw ClusterError("a message came from " + name(r) + " out of turn");
        Holder& holder = held[std::size_t(r)];
        holder.heard = Clock::now();
        std::uint8_t kind = 0;
        bool complete = false;
        std::optional<RenderState> state;
        try {
            ByteReader<> in = reader_of(message);
            kind = in.u8();
            if (in.i32() != holder.frame) throw std::runtime_error("news of another frame");
            if (kind == std::uint8_t(FrameMessage::alive)) return;
            if (kind != std::uint8_t(FrameMessage::checkpoint) &&
                kind != std::uint8_t(FrameMessage::done))
                throw std::runtime_error("a message of an unknown kind");
            complete = in.u8() != 0;
            state.emplace(book.fresh_state(holder.frame));
            read_state(in, *state, rendering.tile_size);
            if (in.left() != 0) throw std::runtime_error("bytes past its end");
        } catch (const std::runtime_error& e) {
            throw ClusterError("a message from " + name(r) + " makes no sense: " + e.what());
        }
        // Outside the try: a frame that cannot be written is not the rank's fault.
        if (kind == std::uint8_t(FrameMessage::checkpoint))
            book.checkpoint(holder.frame, *state);
        else
            finish(std::exchange(holder.frame, -1), r, *state, complete);
    };
    const auto check_answers_come = [&] {
        const auto now = Clock::now();
        for (int r = 1; r < ranks; ++r) {
            const Holder& holder = held[std::size_t(r)];
            if (holder.frame >= 0 && now - holder.heard > cluster.rank_timeout)
                throw ClusterError(
                    name(r) + " has said nothing for " +
                    std::to_string(int(std::chrono::duration<double>(now - holder.heard).count())) +
                    " s while rendering frame " + std::to_string(holder.frame) + " (the limit is " +
                    std::to_string(
                        int(std::chrono::duration<double>(cluster.rank_timeout).count())) +
                    " s): it stopped, or its host is unreachable");
        }
    };

    for (;;) {
        if (const std::exception_ptr error = local.error()) std::rethrow_exception(error);
        if ((progress.stop_after_pass || progress.cancel) && !stopping) {
            stopping = true;
            at_once = progress.cancel;
            stop_all(at_once);
        } else if (stopping && progress.cancel && !at_once) {
            at_once = true;
            stop_all(true);
        }
        if (const std::optional<Message> message = transport.receive(std::chrono::milliseconds(2)))
            take_message(*message);
        if (const std::optional<FrameRenderer::Checkpoint> c = local.take_checkpoint()) {
            RenderState state = book.fresh_state(c->frame);
            ByteReader<> in(reinterpret_cast<const unsigned char*>(c->state.data()),
                            c->state.size(), "a checkpoint was cut short");
            read_state(in, state, rendering.tile_size);
            book.checkpoint(c->frame, state);
        }
        if (std::optional<FrameRenderer::Done> done = local.take_done())
            finish(done->frame, 0, done->state, done->complete);
        if (!stopping)
            for (int r = 0; r < ranks && !queue.empty(); ++r)
                if (r == 0 ? !local.busy() : held[std::size_t(r)].frame < 0) hand_out(r);
        const bool idle = !local.busy() && std::none_of(held.begin(), held.end(),
                                                        [](auto& h) { return h.frame >= 0; });
        if (idle && (stopping || queue.empty())) break;
        check_answers_come();
    }
    if (const std::exception_ptr error = local.error()) std::rethrow_exception(error);
    for (int r = 1; r < ranks; ++r) transport.send(r, short_message(FrameMessage::over, 0));
    if (frames_by_rank) *frames_by_rank = by_rank;
    return all_complete && queue.empty();
}

void share_frames_as_worker(Transport& transport, const FrameRendering& rendering) {
    FrameRenderer renderer(rendering);
    auto last_word = Clock::now();
    const auto send = [&](const std::string& bytes) {
        transport.send(0, bytes);
        last_word = Clock::now();
    };
    for (;;) {
        if (const std::exception_ptr error = renderer.error()) std::rethrow_exception(error);
        if (const std::optional<Message> message =
                transport.receive(std::chrono::milliseconds(20))) {
            if (message->from != 0) throw ClusterError("a message came from a rank other than 0");
            ByteReader<> in = reader_of(*message);
            const std::uint8_t kind = in.u8();
            if (kind == std::uint8_t(FrameMessage::over)) {
                if (renderer.busy()) throw ClusterError("rank 0 ended the frames while one runs");
                return;
            }
            if (kind == std::uint8_t(FrameMessage::stop)) {
                renderer.stop(in.i32() != 0);
            } else if (kind == std::uint8_t(FrameMessage::frame)) {
                if (renderer.busy()) throw ClusterError("rank 0 sent a frame while one runs");
                const int frame = in.i32();
                std::string text = in.text();
                const bool has_state = in.u8() != 0;
                FrameRenderer::Load load;
                if (has_state)  // the state is the rest of the message
                    load = [bytes = message->bytes.substr(message->bytes.size() - in.left()),
                            tile_size = rendering.tile_size](RenderState& state) {
                        ByteReader<> rest(reinterpret_cast<const unsigned char*>(bytes.data()),
                                          bytes.size(), "a message from rank 0 was cut short");
                        read_state(rest, state, tile_size);
                    };
                renderer.start(frame, std::move(load),
                               text.empty() ? std::nullopt : std::optional(std::move(text)));
                last_word = Clock::now();
            } else {
                throw ClusterError("rank 0 sent a message of an unknown kind");
            }
        }
        if (const std::optional<FrameRenderer::Checkpoint> c = renderer.take_checkpoint())
            send(state_message(FrameMessage::checkpoint, c->frame, c->state));
        if (const std::optional<FrameRenderer::Done> done = renderer.take_done())
            send(state_message(FrameMessage::done, done->frame,
                               encoded(done->state, rendering.tile_size), done->complete));
        else if (renderer.busy() && Clock::now() - last_word >= rendering.heartbeat)
            send(short_message(FrameMessage::alive, renderer.frame()));
    }
}

}  // namespace glint
