#pragma once
// Per-frame timing gathered on the master: each rank's render time, the frame's wall-clock
// time, and what follows from them (frames/s, pixels/s, load imbalance = max/mean render time).
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace aurorawall::cluster {

// Room in a RankReport for the setFrame time of every component a scene can list.
inline constexpr int kMaxComponents = 16;

// What each rank reports to the master after drawing a frame: the frame it drew (so the
// master can show every rank drew the same one) and how long it took.
// The phases follow MPIglut's perflib: prepare (per-frame CPU work), render, wait (for the slowest
// rank), swap.
struct RankReport {
    std::uint64_t frame = 0;
    double timeS = 0.0;
    double prepareMs = 0.0;   // per-frame component work on the CPU (curtain map), wall time
    double prepareCpuMs = 0.0; // the same as CPU time of the process
    double renderMs = 0.0;    // its bands drawn and finished (glFinish), those of other ranks'
                              // screens read back, wall time
    double renderCpuMs = 0.0; // CPU time of the whole process while rendering, all threads
                              // (llvmpipe's included): the rank's own work, even on a shared machine
    double renderGpuMs = -1.0; // the GPU's time drawing its bands, from GL_TIMESTAMP queries around each
                               // draw (gl/gpu_timer.h); -1 where they are not used (Mesa's CPU renderers)
    double exchangeMs = 0.0;  // load balancing: sending, receiving and uploading band pixels
    double exchangeMB = 0.0;  // megabytes this rank sent plus received: compressed band pixels
    double renderWork = 0.0;  // load balancing: the work of the rays it drew, the sum over its drawn
                              // pixels of 1 + aurora samples (main.frag's work output): a noise-free
                              // measure of its share (0 with the static split, which measures nothing)
    double waitMs = 0.0;      // waiting for the other ranks: for this frame's message after its
                              // report of the previous frame (the slowest rank of that frame, the
                              // gather and the broadcast), plus the swap barrier with windows
    double swapMs = 0.0;      // presenting and swapping its windows
    std::int32_t closeRequested = 0; // a window of this rank was closed
    std::int32_t stopSignal = 0;     // this rank received SIGINT or SIGTERM (its number; 0: none)
    // Each listed component's setFrame (its per-frame work, GPU work it waits for included), wall
    // time, ms, in the scene's component order: prepareMs split by component.
    double componentMs[kMaxComponents] = {};
};

struct FrameRecord {
    std::uint64_t frame = 0;
    double timeS = 0.0;          // animation time
    double frameMs = 0.0;        // the master's wall clock, from the broadcast to the reports gathered
    std::vector<RankReport> ranks;

    double maxRenderMs() const;
    double meanRenderMs() const;
    double imbalance() const; // max / mean; 1 is perfect balance
};

class FrameStats {
public:
    // componentNames: the scene's components in order, naming RankReport::componentMs; at most
    // kMaxComponents (std::length_error otherwise).
    explicit FrameStats(double pixelsPerFrame, std::vector<std::string> componentNames = {});

    // Keeps the frame's record, and with streamCsv writes its row and flushes it (std::runtime_error
    // "--stats PATH: write failed (REASON)" if it cannot).
    void add(FrameRecord record);
    const std::vector<FrameRecord>& records() const { return records_; }

    // "frame 3  t=0.100 s  41.2 ms  24.3 fps  22.4 Mpixel/s  imbalance 1.07", then the setFrame of
    // each component that took 0.05 ms or more on some rank (its largest over the ranks):
    // "  setFrame plasma 12.3 ms".
    std::string frameLine(const FrameRecord& r) const;
    // Means over all frames but the first (which includes shader compilation and warm-up).
    std::string summary() const;

    // CSV (one row per frame, one render_ms column per rank, a setframe_ms_NAME column per component
    // and rank) or JSON (each rank's "component_ms": {"NAME": ms, ...}), chosen by the extension (.csv
    // or .json); written atomically. Nothing for the file streamCsv writes: it is complete.
    void write(const std::string& path) const;

    // Writes the CSV header for `ranks` ranks to `path`, then each frame's row as it is added, each
    // flushed, so that a run that fails or is stopped keeps every frame drawn. Throws std::runtime_error.
    void streamCsv(const std::string& path, size_t ranks);

private:
    void appendToStream(const std::string& text);
    std::string csvHeader(size_t ranks) const;
    std::string csvRow(const FrameRecord& f) const;

    struct FileCloser {
        void operator()(std::FILE* f) const { std::fclose(f); }
    };
    std::unique_ptr<std::FILE, FileCloser> stream_;
    std::string streamPath_;
    double pixelsPerFrame_;
    std::vector<std::string> componentNames_;
    std::vector<FrameRecord> records_;
};

} // namespace aurorawall::cluster
