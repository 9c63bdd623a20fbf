#include "parallel/Communicator.H"

#include <cstdlib>
#include <stdexcept>

namespace gpic {

namespace {

class SerialCommunicator final : public Communicator {
public:
    int rank() const override { return 0; }
    int size() const override { return 1; }
    void sumInRankOrder(std::vector<double>&) const override {}
    void min(std::vector<double>&) const override {}
    std::vector<std::vector<char>> exchange(const std::vector<int>& peers,
                                            const std::vector<std::vector<char>>&) const override
    {
        if (!peers.empty()) throw std::logic_error("a serial run has no peers to exchange with");
        return {};
    }
    [[noreturn]] void abort(int status) const override { std::exit(status); }
};

} // namespace

std::unique_ptr<Communicator> serialCommunicator() { return std::make_unique<SerialCommunicator>(); }

} // namespace gpic
