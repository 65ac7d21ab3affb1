#include "cluster/frame_stats.h"

#include "io/atomic_file.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace aurorawall::cluster {

double FrameRecord::maxRenderMs() const
{
    double m = 0.0;
    for (const RankReport& r : ranks)
        m = std::max(m, r.renderMs);
    return m;
}

double FrameRecord::meanRenderMs() const
{
    double sum = 0.0;
    for (const RankReport& r : ranks)
        sum += r.renderMs;
    return ranks.empty() ? 0.0 : sum / static_cast<double>(ranks.size());
}

double FrameRecord::imbalance() const
{
    const double mean = meanRenderMs();
    return mean > 0.0 ? maxRenderMs() / mean : 1.0;
}

FrameStats::FrameStats(double pixelsPerFrame, std::vector<std::string> componentNames)
    : pixelsPerFrame_(pixelsPerFrame), componentNames_(std::move(componentNames))
{
    if (componentNames_.size() > size_t(kMaxComponents))
        throw std::length_error("the stats have room for " + std::to_string(kMaxComponents) + " components, not " +
                                std::to_string(componentNames_.size()));
}

std::string FrameStats::frameLine(const FrameRecord& r) const
{
    std::ostringstream s;
    s.setf(std::ios::fixed);
    s.precision(3);
    s << "frame " << r.frame << "  t=" << r.timeS << " s  ";
    s.precision(1);
    s << r.frameMs << " ms  " << 1000.0 / r.frameMs << " fps  " << pixelsPerFrame_ / (r.frameMs * 1e3)
      << " Mpixel/s  render max " << r.maxRenderMs() << " ms mean " << r.meanRenderMs() << " ms  imbalance ";
    s.precision(2);
    s << r.imbalance();
    s.precision(1);
    for (size_t c = 0; c < componentNames_.size(); ++c) {
        double ms = 0.0;
        for (const RankReport& rank : r.ranks)
            ms = std::max(ms, rank.componentMs[c]);
        if (ms >= 0.05)
            s << "  setFrame " << componentNames_[c] << " " << ms << " ms";
    }
    return s.str();
}

std::string FrameStats::summary() const
{
    const size_t first = records_.size() > 1 ? 1 : 0;
    double frameMs = 0, imbalance = 0, renderMax = 0;
    for (size_t i = first; i < records_.size(); ++i) {
        frameMs += records_[i].frameMs;
        imbalance += records_[i].imbalance();
        renderMax += records_[i].maxRenderMs();
    }
    const double n = static_cast<double>(records_.size() - first);
    if (n == 0)
        return "no frames rendered";
    std::ostringstream s;
    s.setf(std::ios::fixed);
    s.precision(2);
    s << records_.size() << " frames (" << (first ? "first excluded as warm-up" : "one frame")
      << "): " << 1000.0 * n / frameMs << " fps, " << pixelsPerFrame_ * n / (frameMs * 1e3) << " Mpixel/s, "
      << "frame " << frameMs / n << " ms, slowest rank " << renderMax / n << " ms, imbalance " << imbalance / n;
    return s.str();
}

std::string FrameStats::csvHeader(size_t ranks) const
{
    std::ostringstream out;
    out << "frame,time_s,frame_ms,fps,mpixel_per_s,render_max_ms,render_mean_ms,imbalance";
    for (size_t r = 0; r < ranks; ++r)
        out << ",frame_rank" << r << ",time_s_rank" << r << ",prepare_ms_rank" << r << ",prepare_cpu_ms_rank" << r
            << ",render_ms_rank" << r << ",render_cpu_ms_rank" << r << ",render_gpu_ms_rank" << r << ",exchange_ms_rank"
            << r << ",exchange_mb_rank" << r << ",wait_ms_rank" << r << ",swap_ms_rank" << r << ",render_work_rank" << r;
    for (size_t r = 0; r < ranks; ++r)
        for (const std::string& name : componentNames_)
            out << ",setframe_ms_" << name << "_rank" << r;
    out << "\n";
    return out.str();
}

std::string FrameStats::csvRow(const FrameRecord& f) const
{
    std::ostringstream out;
    out.precision(9);
    out << f.frame << "," << f.timeS << "," << f.frameMs << "," << 1000.0 / f.frameMs << ","
        << pixelsPerFrame_ / (f.frameMs * 1e3) << "," << f.maxRenderMs() << "," << f.meanRenderMs() << ","
        << f.imbalance();
    for (const RankReport& r : f.ranks)
        out << "," << r.frame << "," << r.timeS << "," << r.prepareMs << "," << r.prepareCpuMs << "," << r.renderMs
            << "," << r.renderCpuMs << "," << r.renderGpuMs << "," << r.exchangeMs << "," << r.exchangeMB << ","
            << r.waitMs << "," << r.swapMs << "," << r.renderWork;
    for (const RankReport& r : f.ranks)
        for (size_t c = 0; c < componentNames_.size(); ++c)
            out << "," << r.componentMs[c];
    out << "\n";
    return out.str();
}

void FrameStats::streamCsv(const std::string& path, size_t ranks)
{
    stream_.reset(std::fopen(path.c_str(), "w"));
    if (!stream_)
        throw std::runtime_error("--stats " + path + ": cannot write (" + std::strerror(errno) + ")");
    streamPath_ = path;
    appendToStream(csvHeader(ranks));
}

void FrameStats::appendToStream(const std::string& text)
{
    if (std::fwrite(text.data(), 1, text.size(), stream_.get()) != text.size() || std::fflush(stream_.get()) != 0)
        throw std::runtime_error("--stats " + streamPath_ + ": write failed (" + std::strerror(errno) + ")");
}

void FrameStats::add(FrameRecord record)
{
    records_.push_back(std::move(record));
    if (stream_)
        appendToStream(csvRow(records_.back()));
}

void FrameStats::write(const std::string& path) const
{
    if (stream_ && path == streamPath_)
        return; // every frame's row is written and flushed already
    const bool json = path.size() >= 5 && path.compare(path.size() - 5, 5, ".json") == 0;
    const bool csv = path.size() >= 4 && path.compare(path.size() - 4, 4, ".csv") == 0;
    if (!json && !csv)
        throw std::invalid_argument("--stats " + path + ": the file name must end in .csv or .json");
    std::ostringstream out;
    out.precision(9);
    if (csv) {
        out << csvHeader(records_.empty() ? 0 : records_.front().ranks.size());
        for (const FrameRecord& f : records_)
            out << csvRow(f);
    } else {
        out << "{\n  \"pixels_per_frame\": " << pixelsPerFrame_ << ",\n  \"frames\": [";
        for (size_t i = 0; i < records_.size(); ++i) {
            const FrameRecord& f = records_[i];
            out << (i ? ",\n" : "\n") << "    {\"frame\": " << f.frame << ", \"time_s\": " << f.timeS
                << ", \"frame_ms\": " << f.frameMs << ", \"imbalance\": " << f.imbalance() << ", \"ranks\": [";
            for (size_t r = 0; r < f.ranks.size(); ++r) {
                out << (r ? ", " : "") << "{\"frame\": " << f.ranks[r].frame << ", \"time_s\": " << f.ranks[r].timeS
                    << ", \"prepare_ms\": " << f.ranks[r].prepareMs << ", \"prepare_cpu_ms\": " << f.ranks[r].prepareCpuMs
                    << ", \"render_ms\": " << f.ranks[r].renderMs
                    << ", \"render_cpu_ms\": " << f.ranks[r].renderCpuMs << ", \"render_gpu_ms\": " << f.ranks[r].renderGpuMs
                    << ", \"exchange_ms\": " << f.ranks[r].exchangeMs << ", \"exchange_mb\": " << f.ranks[r].exchangeMB
                    << ", \"wait_ms\": " << f.ranks[r].waitMs
                    << ", \"swap_ms\": " << f.ranks[r].swapMs << ", \"render_work\": " << f.ranks[r].renderWork
                    << ", \"component_ms\": {";
                for (size_t c = 0; c < componentNames_.size(); ++c)
                    out << (c ? ", " : "") << "\"" << componentNames_[c] << "\": " << f.ranks[r].componentMs[c];
                out << "}}";
            }
            out << "]}";
        }
        out << "\n  ]\n}\n";
    }
    try {
        io::writeFileAtomically(path, [&](const std::string& temporary) {
            std::ofstream file(temporary);
            file << out.str();
            if (!file.flush())
                throw std::runtime_error(std::strerror(errno));
        });
    } catch (const std::exception& e) {
        throw std::runtime_error("--stats " + path + ": cannot write (" + e.what() + ")");
    }
}

} // namespace aurorawall::cluster
