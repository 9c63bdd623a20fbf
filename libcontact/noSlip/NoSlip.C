#include "noSlip/NoSlip.H"

namespace gpic {

GPIC_REGISTER(ContactLaw, NoSlip, "noSlip")

} // namespace gpic
