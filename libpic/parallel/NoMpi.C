// A build without MPI: one rank alone (parallel/Communicator.H).
#include "parallel/Communicator.H"

#include <stdexcept>

namespace gpic {

bool mpiAvailable() { return false; }

std::unique_ptr<Communicator> mpiCommunicator(int*, char***)
{
    throw std::logic_error("mpiCommunicator: this build has no MPI");
}

} // namespace gpic
