#include "cluster/watchdog.h"

#include "cluster/silence_watch.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>

namespace aurorawall::cluster {

namespace {

constexpr int kHeartbeatTag = 1;

double secondsNow()
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// "rank 2 (last heard: drawing frame 12, 10.0 s ago)", joined by "; ".
std::string describeSilent(const std::vector<SilenceWatch::Silent>& silent)
{
    std::string text;
    for (const SilenceWatch::Silent& s : silent) {
        char ago[32];
        std::snprintf(ago, sizeof ago, "%.1f", s.silentS);
        text += (text.empty() ? "" : "; ") + std::string("rank ") + std::to_string(s.rank) +
                " (last heard: " + describePhase(s.phase, s.frame) + ", " + ago + " s ago)";
    }
    return text;
}

} // namespace

Watchdog::Watchdog(MPI_Comm comm, double timeoutS) : comm_(comm), timeoutS_(timeoutS)
{
    MPI_Comm_rank(comm_, &rank_);
    MPI_Comm_size(comm_, &size_);
    if (size_ == 1)
        return;
    thread_ = std::thread([this] { rank_ == 0 ? watchRanks() : sendHeartbeats(); });
}

Watchdog::~Watchdog()
{
    stop_ = true;
    if (thread_.joinable())
        thread_.join();
}

void Watchdog::setPhase(RankPhase phase, std::uint64_t frame)
{
    frame_ = frame;
    phase_ = static_cast<std::int64_t>(phase);
}

void Watchdog::sendHeartbeats()
{
    const auto period = std::chrono::duration<double>(std::clamp(timeoutS_ / 5.0, 0.05, 1.0));
    const auto tick = std::chrono::milliseconds(10); // how soon the thread notices it should stop
    auto next = std::chrono::steady_clock::now();
    while (true) {
        const bool last = stop_;
        if (last || std::chrono::steady_clock::now() >= next) {
            // A small message goes eagerly: MPI_Send returns without waiting for the master to receive it.
            std::int64_t beat[2] = {last ? static_cast<std::int64_t>(RankPhase::Finished) : phase_.load(),
                                    static_cast<std::int64_t>(frame_.load())};
            MPI_Send(beat, 2, MPI_INT64_T, 0, kHeartbeatTag, comm_);
            next = std::chrono::steady_clock::now() +
                   std::chrono::duration_cast<std::chrono::steady_clock::duration>(period);
        }
        if (last)
            return;
        std::this_thread::sleep_for(tick);
    }
}

void Watchdog::watchRanks()
{
    SilenceWatch watch(size_, timeoutS_, secondsNow());
    std::int64_t beat[2] = {0, 0};
    MPI_Request request;
    MPI_Irecv(beat, 2, MPI_INT64_T, MPI_ANY_SOURCE, kHeartbeatTag, comm_, &request);
    while (!stop_) {
        int arrived = 0;
        MPI_Status status;
        MPI_Test(&request, &arrived, &status);
        if (arrived) {
            watch.heard(status.MPI_SOURCE, static_cast<RankPhase>(beat[0]), static_cast<std::uint64_t>(beat[1]),
                        secondsNow());
            MPI_Irecv(beat, 2, MPI_INT64_T, MPI_ANY_SOURCE, kHeartbeatTag, comm_, &request);
            continue;
        }
        const std::vector<SilenceWatch::Silent> silent = watch.silentRanks(secondsNow());
        if (!silent.empty()) {
            std::fprintf(stderr,
                         "aurorawall render: no heartbeat for more than --rank-timeout %g s from %s; the master "
                         "was in %s; ending the job (exit status %d)\n",
                         timeoutS_, describeSilent(silent).c_str(),
                         describePhase(static_cast<RankPhase>(phase_.load()), frame_.load()).c_str(),
                         kRankSilentExitStatus);
            std::fflush(stderr);
            MPI_Abort(MPI_COMM_WORLD, kRankSilentExitStatus);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    MPI_Cancel(&request);
    MPI_Wait(&request, MPI_STATUS_IGNORE);
}

} // namespace aurorawall::cluster
