// MPI behind the Communicator (compiled where the build found MPI: libpic/CMakeLists.txt;
// NoMpi.C otherwise).
#include "parallel/Communicator.H"

#include <mpi.h>

#include <cstdlib>
#include <exception>
#include <stdexcept>
#include <string>

namespace gpic {

namespace {

void check(int code, const char* what)
{
    if (code != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + what + " failed");
}

class MpiCommunicator final : public Communicator {
public:
    MpiCommunicator(int* argc, char*** argv)
    {
        int ready = 0;
        MPI_Initialized(&ready);
        if (!ready) {
            check(MPI_Init(argc, argv), "MPI_Init");
            owner_ = true;
        }
        MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
        MPI_Comm_size(MPI_COMM_WORLD, &size_);
    }
    ~MpiCommunicator() override
    {
        // A rank that fails leaves without MPI_Finalize, which would wait for the others:
        // mpirun then ends the whole job with that rank's exit status and its message.
        if (std::uncaught_exceptions() > 0) return;
        int finalized = 0;
        MPI_Finalized(&finalized);
        if (owner_ && !finalized) MPI_Finalize();
    }
    int rank() const override { return rank_; }
    int size() const override { return size_; }

    void sumInRankOrder(std::vector<double>& values) const override
    {
        // Every rank gets every rank's values and adds them in rank order itself: MPI's own
        // reductions may combine in an order of their choosing.
        const int n = static_cast<int>(values.size());
        std::vector<double> all(static_cast<std::size_t>(n) * size_);
        check(MPI_Allgather(values.data(), n, MPI_DOUBLE, all.data(), n, MPI_DOUBLE, MPI_COMM_WORLD), "MPI_Allgather");
        for (int i = 0; i < n; ++i) {
            double sum = all[i];
            for (int r = 1; r < size_; ++r) sum += all[static_cast<std::size_t>(r) * n + i];
            values[i] = sum;
        }
    }

    void min(std::vector<double>& values) const override
    {
        check(MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_MIN,
                            MPI_COMM_WORLD),
              "MPI_Allreduce");
    }

    std::vector<std::vector<char>> exchange(const std::vector<int>& peers,
                                            const std::vector<std::vector<char>>& send) const override
    {
        // Sizes first, then the bytes; non-blocking both ways, so no pair waits on the other.
        const std::size_t n = peers.size();
        std::vector<unsigned long> sendSize(n), receiveSize(n);
        std::vector<MPI_Request> requests(2 * n);
        for (std::size_t k = 0; k < n; ++k) {
            sendSize[k] = send[k].size();
            MPI_Irecv(&receiveSize[k], 1, MPI_UNSIGNED_LONG, peers[k], 1, MPI_COMM_WORLD, &requests[2 * k]);
            MPI_Isend(&sendSize[k], 1, MPI_UNSIGNED_LONG, peers[k], 1, MPI_COMM_WORLD, &requests[2 * k + 1]);
        }
        check(MPI_Waitall(static_cast<int>(2 * n), requests.data(), MPI_STATUSES_IGNORE), "exchanging sizes");
        std::vector<std::vector<char>> received(n);
        for (std::size_t k = 0; k < n; ++k) {
            received[k].resize(receiveSize[k]);
            MPI_Irecv(received[k].data(), static_cast<int>(receiveSize[k]), MPI_BYTE, peers[k], 2, MPI_COMM_WORLD,
                      &requests[2 * k]);
            MPI_Isend(send[k].data(), static_cast<int>(sendSize[k]), MPI_BYTE, peers[k], 2, MPI_COMM_WORLD,
                      &requests[2 * k + 1]);
        }
        check(MPI_Waitall(static_cast<int>(2 * n), requests.data(), MPI_STATUSES_IGNORE), "exchanging data");
        return received;
    }

    [[noreturn]] void abort(int status) const override
    {
        MPI_Abort(MPI_COMM_WORLD, status);
        std::exit(status);  // MPI_Abort does not return; the compiler is not told so
    }

private:
    int rank_ = 0, size_ = 1;
    bool owner_ = false;
};

} // namespace

bool mpiAvailable() { return true; }

std::unique_ptr<Communicator> mpiCommunicator(int* argc, char*** argv)
{
    return std::make_unique<MpiCommunicator>(argc, argv);
}

} // namespace gpic
