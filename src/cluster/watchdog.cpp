#include "cluster/watchdog.h"

#include "cluster/silence_watch.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace aurorawall::cluster {

namespace {

constexpr int kHeartbeatTag = 1;
constexpr int kHeartbeatValues = 4;
constexpr int kMasterBeatTag = 2; // the master's heartbeat to each worker: one int64, 1 while it runs, 0 when done

double secondsNow()
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// "rank 2 on node7 (last heard: drawing frame 12, 10.0 s ago)", joined by "; ".
std::string describeSilent(const std::vector<SilenceWatch::Silent>& silent, const std::vector<std::string>& hosts)
{
    std::string text;
    for (const SilenceWatch::Silent& s : silent) {
        char ago[32];
        std::snprintf(ago, sizeof ago, "%.1f", s.silentS);
        text += (text.empty() ? "" : "; ") + std::string("rank ") + std::to_string(s.rank) + " on " +
                hosts[std::size_t(s.rank)] + " (last heard: " + describePhase(s.phase, s.frame) + ", " + ago +
                " s ago)";
    }
    return text;
}

// "rank 2 on node7 (drawing frame 3, its main thread without progress for 4.1 s)", joined by "; ".
std::string describeHung(const std::vector<SilenceWatch::Hung>& hung, const std::vector<std::string>& hosts)
{
    std::string text;
    for (const SilenceWatch::Hung& h : hung) {
        char stalled[32];
        std::snprintf(stalled, sizeof stalled, "%.1f", h.beat.stalledS);
        text += (text.empty() ? "" : "; ") + std::string("rank ") + std::to_string(h.rank) + " on " +
                hosts[std::size_t(h.rank)] + " (" + describePhase(h.beat.phase, h.beat.frame) +
                ", its main thread without progress for " + stalled + " s)";
    }
    return text;
}

} // namespace

double heartbeatPeriodS(double timeoutS) { return std::clamp(timeoutS / 5.0, 0.05, 1.0); }

Watchdog::Watchdog(MPI_Comm comm, double timeoutS) : comm_(comm), timeoutS_(timeoutS), progress_(secondsNow())
{
    MPI_Comm_rank(comm_, &rank_);
    MPI_Comm_size(comm_, &size_);
    // Every rank's host, for the messages that name a silent rank (collective: every rank makes its
    // watchdog at the same point).
    char name[MPI_MAX_PROCESSOR_NAME] = {};
    int length = 0;
    MPI_Get_processor_name(name, &length);
    std::vector<char> names(std::size_t(size_) * MPI_MAX_PROCESSOR_NAME, '\0');
    MPI_Allgather(name, MPI_MAX_PROCESSOR_NAME, MPI_CHAR, names.data(), MPI_MAX_PROCESSOR_NAME, MPI_CHAR, comm_);
    for (int r = 0; r < size_; ++r)
        hosts_.emplace_back(names.data() + std::size_t(r) * MPI_MAX_PROCESSOR_NAME);
    unsigned long long hangFrame = 0;
    if (const char* hang = std::getenv("AURORAWALL_TEST_HANG_MAIN_THREAD");
        hang && std::sscanf(hang, "%d:%llu", &hangRank_, &hangFrame) == 2)
        hangFrame_ = hangFrame;
    else
        hangRank_ = -1;
    if (rank_ == 0)
        watch_.emplace(size_, timeoutS_, secondsNow());
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
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        progress_.phaseChanged(phase, frame, secondsNow());
    }
    while (rank_ == hangRank_ && phase == RankPhase::Draw && frame == hangFrame_)
        std::this_thread::sleep_for(std::chrono::hours(1));
}

void Watchdog::waitBegins()
{
    const std::lock_guard<std::mutex> lock(mutex_);
    progress_.waitBegins(secondsNow());
}

void Watchdog::waitEnds()
{
    const std::lock_guard<std::mutex> lock(mutex_);
    progress_.waitEnds(secondsNow());
}

std::vector<double> Watchdog::heartbeatAgesS()
{
    const std::lock_guard<std::mutex> lock(watchMutex_);
    return watch_ ? watch_->heartbeatAgesS(secondsNow()) : std::vector<double>{};
}

MainThreadProgress::Snapshot Watchdog::progress()
{
    const std::lock_guard<std::mutex> lock(mutex_);
    return progress_.at(secondsNow());
}

void Watchdog::sendHeartbeats()
{
    const auto period = std::chrono::duration<double>(heartbeatPeriodS(timeoutS_));
    const auto tick = std::chrono::milliseconds(10); // how soon the thread notices it should stop
    auto next = std::chrono::steady_clock::now();
    // The master's heartbeats: a master silent for longer than the timeout (stopped, frozen, cut off)
    // ends the job, as the master does for a silent worker; its last beat says it has finished.
    std::int64_t masterBeat = 1;
    MPI_Request fromMaster;
    MPI_Irecv(&masterBeat, 1, MPI_INT64_T, 0, kMasterBeatTag, comm_, &fromMaster);
    double masterHeardS = secondsNow();
    bool masterFinished = false;
    while (true) {
        const bool last = stop_;
        if (last || std::chrono::steady_clock::now() >= next) {
            // A small message goes eagerly: MPI_Send returns without waiting for the master to receive it.
            // Phase, frame, waiting for other ranks (0 or 1), microseconds without progress.
            const MainThreadProgress::Snapshot p = progress();
            std::int64_t beat[kHeartbeatValues] = {
                static_cast<std::int64_t>(last ? RankPhase::Finished : p.phase), static_cast<std::int64_t>(p.frame),
                p.waiting ? 1 : 0, static_cast<std::int64_t>(p.stalledS * 1e6)};
            MPI_Send(beat, kHeartbeatValues, MPI_INT64_T, 0, kHeartbeatTag, comm_);
            next = std::chrono::steady_clock::now() +
                   std::chrono::duration_cast<std::chrono::steady_clock::duration>(period);
        }
        int arrived = 1;
        while (!masterFinished && arrived) {
            MPI_Test(&fromMaster, &arrived, MPI_STATUS_IGNORE);
            if (arrived) {
                masterHeardS = secondsNow();
                masterFinished = masterBeat == 0;
                if (!masterFinished)
                    MPI_Irecv(&masterBeat, 1, MPI_INT64_T, 0, kMasterBeatTag, comm_, &fromMaster);
            }
        }
        if (last)
            break;
        if (!masterFinished && secondsNow() - masterHeardS > timeoutS_) {
            const MainThreadProgress::Snapshot p = progress();
            std::fprintf(stderr,
                         "aurorawall render: rank %d on %s: no heartbeat for more than --rank-timeout %g s from the "
                         "master (rank 0 on %s: stopped, frozen or unreachable); this rank was in %s; ending the job "
                         "(exit status %d)\n",
                         rank_, hosts_[std::size_t(rank_)].c_str(), timeoutS_, hosts_[0].c_str(),
                         describePhase(p.phase, p.frame).c_str(), kRankSilentExitStatus);
            std::fflush(stderr);
            MPI_Abort(MPI_COMM_WORLD, kRankSilentExitStatus);
        }
        // A sleep that overran its tick by more than a heartbeat period (this process stopped, or starved of
        // CPU) is no silence of the master's: a rank resumed after a SIGSTOP would otherwise blame the master
        // for its own stop. Overruns shorter than that are the scheduler's, and count.
        const double sleepStartS = secondsNow();
        std::this_thread::sleep_for(tick);
        const double overrunS = secondsNow() - sleepStartS - std::chrono::duration<double>(tick).count();
        if (overrunS > period.count())
            masterHeardS += overrunS;
    }
    if (!masterFinished) {
        MPI_Cancel(&fromMaster);
        MPI_Wait(&fromMaster, MPI_STATUS_IGNORE);
    }
}

void Watchdog::watchRanks()
{
    std::int64_t beat[kHeartbeatValues] = {};
    MPI_Request request;
    MPI_Irecv(beat, kHeartbeatValues, MPI_INT64_T, MPI_ANY_SOURCE, kHeartbeatTag, comm_, &request);
    // The master's own heartbeat to every worker, at the workers' period (eager: MPI_Send returns).
    const double beatPeriodS = heartbeatPeriodS(timeoutS_);
    double nextBeatS = 0.0;
    const auto beatWorkers = [this](std::int64_t running) {
        for (int r = 1; r < size_; ++r)
            MPI_Send(&running, 1, MPI_INT64_T, r, kMasterBeatTag, comm_);
    };
    while (!stop_) {
        if (secondsNow() >= nextBeatS) {
            beatWorkers(1);
            nextBeatS = secondsNow() + beatPeriodS;
        }
        int arrived = 0;
        MPI_Status status;
        MPI_Test(&request, &arrived, &status);
        if (arrived) {
            const std::lock_guard<std::mutex> lock(watchMutex_);
            watch_->heard(status.MPI_SOURCE,
                          {static_cast<RankPhase>(beat[0]), static_cast<std::uint64_t>(beat[1]), beat[2] != 0,
                           static_cast<double>(beat[3]) * 1e-6},
                          secondsNow());
            MPI_Irecv(beat, kHeartbeatValues, MPI_INT64_T, MPI_ANY_SOURCE, kHeartbeatTag, comm_, &request);
            continue;
        }
        const MainThreadProgress::Snapshot master = progress();
        const std::string masterPhase = describePhase(master.phase, master.frame);
        std::unique_lock<std::mutex> lock(watchMutex_);
        const std::vector<SilenceWatch::Silent> silent = watch_->silentRanks(secondsNow());
        const std::vector<SilenceWatch::Hung> hung = watch_->hungRanks(master);
        const double stallLimitS = watch_->stallLimitS(master);
        lock.unlock();
        if (!silent.empty()) {
            std::fprintf(stderr,
                         "aurorawall render: no heartbeat for more than --rank-timeout %g s from %s; the master "
                         "was in %s; ending the job (exit status %d)\n",
                         timeoutS_, describeSilent(silent, hosts_).c_str(), masterPhase.c_str(), kRankSilentExitStatus);
            std::fflush(stderr);
            MPI_Abort(MPI_COMM_WORLD, kRankSilentExitStatus);
        }
        if (!hung.empty()) {
            std::fprintf(stderr,
                         "aurorawall render: hung: %s, more than %.1f s = max(--rank-timeout %g s, %g x max(the "
                         "slowest frame %.2f s, the master's own work this frame %.2f s)); the master was waiting in "
                         "%s; ending the job (exit status %d)\n",
                         describeHung(hung, hosts_).c_str(), stallLimitS, timeoutS_, kFramesBeforeHung,
                         master.slowestFrameS,
                         master.busyThisFrameS, masterPhase.c_str(), kRankSilentExitStatus);
            std::fflush(stderr);
            MPI_Abort(MPI_COMM_WORLD, kRankSilentExitStatus);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    beatWorkers(0); // finished: the workers stop watching
    MPI_Cancel(&request);
    MPI_Wait(&request, MPI_STATUS_IGNORE);
}

WaitingForRanks::WaitingForRanks(Watchdog* watchdog) : watchdog_(watchdog)
{
    if (watchdog_)
        watchdog_->waitBegins();
}

WaitingForRanks::~WaitingForRanks()
{
    if (watchdog_)
        watchdog_->waitEnds();
}

} // namespace aurorawall::cluster
