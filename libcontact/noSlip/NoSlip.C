#include "noSlip/NoSlip.H"

namespace gpic {

GPIC_REGISTER(ContactLaw<2>, NoSlip, "noSlip")

} // namespace gpic
