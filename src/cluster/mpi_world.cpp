#include "cluster/mpi_world.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <numeric>
#include <set>

namespace aurorawall::cluster {

MpiWorld::MpiWorld(int* argc, char*** argv)
{
    // The watchdog's thread calls MPI while the main thread does.
    int provided = MPI_THREAD_SINGLE;
    MPI_Init_thread(argc, argv, MPI_THREAD_MULTIPLE, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    MPI_Comm node = MPI_COMM_NULL;
    MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &node);
    MPI_Comm_rank(node, &nodeRank_);
    MPI_Comm_free(&node);
    if (provided < MPI_THREAD_MULTIPLE && rank_ == 0)
        std::fprintf(stderr, "aurorawall: this MPI library does not offer MPI_THREAD_MULTIPLE; "
                             "no watchdog for silent ranks\n");
    if (provided == MPI_THREAD_MULTIPLE)
        MPI_Comm_dup(MPI_COMM_WORLD, &heartbeatComm_);
}

MpiWorld::~MpiWorld()
{
    watchdog_.reset();
    if (heartbeatComm_ != MPI_COMM_NULL)
        MPI_Comm_free(&heartbeatComm_);
    MPI_Finalize();
}

void MpiWorld::startWatchdog(double timeoutS) const
{
    if (heartbeatComm_ != MPI_COMM_NULL && !watchdog_)
        watchdog_ = std::make_unique<Watchdog>(heartbeatComm_, timeoutS);
}

void MpiWorld::setPhase(RankPhase phase, std::uint64_t frame) const
{
    if (watchdog_)
        watchdog_->setPhase(phase, frame);
}

std::vector<double> MpiWorld::heartbeatAgesS() const
{
    return watchdog_ ? watchdog_->heartbeatAgesS() : std::vector<double>{};
}

int MpiWorld::agreedStatus(int myStatus, const std::string& myError, const std::string& prefix) const
{
    int agreed = 0;
    {
        const WaitingForRanks waiting(watchdog_.get());
        MPI_Allreduce(&myStatus, &agreed, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    }
    if (agreed == 0)
        return 0;
    const std::vector<std::string> errors = gatherStrings(myError);
    if (rank_ == 0) {
        const auto failures = std::count_if(errors.begin(), errors.end(), [](const std::string& e) { return !e.empty(); });
        std::set<std::string> printed;
        for (int r = 0; r < size_; ++r) {
            const std::string& message = errors[static_cast<size_t>(r)];
            if (message.empty() || !printed.insert(message).second)
                continue;
            if (failures == size_ || size_ == 1)
                std::fprintf(stderr, "%s: %s\n", prefix.c_str(), message.c_str());
            else
                std::fprintf(stderr, "%s: rank %d: %s\n", prefix.c_str(), r, message.c_str());
        }
        std::fflush(stderr);
    }
    return agreed;
}

void MpiWorld::broadcast(std::vector<char>& bytes) const
{
    const WaitingForRanks waiting(watchdog_.get());
    MPI_Bcast(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, 0, MPI_COMM_WORLD);
}

int MpiWorld::broadcastInt(int value) const
{
    const WaitingForRanks waiting(watchdog_.get());
    MPI_Bcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD);
    return value;
}

std::vector<char> MpiWorld::gather(const std::vector<char>& mine) const
{
    const int size = static_cast<int>(mine.size());
    std::vector<char> all(rank_ == 0 ? mine.size() * static_cast<size_t>(size_) : 0);
    const WaitingForRanks waiting(watchdog_.get());
    MPI_Gather(mine.data(), size, MPI_BYTE, all.data(), size, MPI_BYTE, 0, MPI_COMM_WORLD);
    return all;
}

void MpiWorld::exchange(const std::vector<Message>& outgoing, const std::vector<Message>& incoming) const
{
    const WaitingForRanks waiting(watchdog_.get());
    std::vector<MPI_Request> requests;
    for (const Message& m : outgoing) {
        requests.emplace_back();
        MPI_Isend(m.bytes->data(), static_cast<int>(m.bytes->size()), MPI_BYTE, m.rank, m.tag, MPI_COMM_WORLD,
                  &requests.back());
    }
    for (const Message& m : incoming) {
        MPI_Message message = MPI_MESSAGE_NULL;
        MPI_Status status;
        MPI_Mprobe(m.rank, m.tag, MPI_COMM_WORLD, &message, &status);
        int size = 0;
        MPI_Get_count(&status, MPI_BYTE, &size);
        m.bytes->resize(static_cast<size_t>(size));
        MPI_Mrecv(m.bytes->data(), size, MPI_BYTE, &message, MPI_STATUS_IGNORE);
    }
    MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
}

void MpiWorld::swapBarrier() const
{
    const WaitingForRanks waiting(watchdog_.get());
    MPI_Barrier(MPI_COMM_WORLD);
}

std::vector<char> MpiWorld::gatherBytes(const std::vector<char>& mine, std::vector<int>& sizesOut) const
{
    const WaitingForRanks waiting(watchdog_.get());
    const int mySize = static_cast<int>(mine.size());
    sizesOut.assign(rank_ == 0 ? static_cast<size_t>(size_) : 0, 0);
    MPI_Gather(&mySize, 1, MPI_INT, sizesOut.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    std::vector<int> displacements(sizesOut.size(), 0);
    if (!sizesOut.empty())
        std::partial_sum(sizesOut.begin(), sizesOut.end() - 1, displacements.begin() + 1);
    std::vector<char> all(rank_ == 0 ? static_cast<size_t>(std::accumulate(sizesOut.begin(), sizesOut.end(), 0)) : 0);
    MPI_Gatherv(mine.data(), mySize, MPI_BYTE, all.data(), sizesOut.data(), displacements.data(), MPI_BYTE, 0,
                MPI_COMM_WORLD);
    return all;
}

std::vector<std::string> MpiWorld::gatherStrings(const std::string& mine) const
{
    std::vector<int> sizes;
    const std::vector<char> all = gatherBytes(std::vector<char>(mine.begin(), mine.end()), sizes);
    std::vector<std::string> strings;
    size_t at = 0;
    for (int size : sizes) {
        strings.emplace_back(all.data() + at, static_cast<size_t>(size));
        at += static_cast<size_t>(size);
    }
    return strings;
}

void MpiWorld::abortJob(int status) const
{
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, status);
    std::abort(); // MPI_Abort does not return
}

} // namespace aurorawall::cluster
