#include "noSlip/NoSlip.H"

namespace gpic {

GPIC_REGISTER_DIMS(ContactLaw, NoSlip, "noSlip")

} // namespace gpic
