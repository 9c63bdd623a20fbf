// Contact without friction, as a user's library would add it: an approaching body loses the
// normal part of its velocity relative to the other, and keeps the tangential part.
//     constant/contactProperties:   libs ("libscenePlugin.so"); law freeSlip;
#include "contact/ContactLaw.H"

namespace scenePlugin {

class FreeSlipLaw : public gpic::ContactLaw<2> {
public:
    FreeSlipLaw(const gpic::Dictionary&, const std::vector<std::string>&) {}
    bool needsBodyFields() const override { return true; }
    gpic::Vector2 correct(const gpic::Vector2& v, const gpic::Vector2& vRef, const gpic::Vector2& n, int,
                          int) const override
    {
        const double approach = (v - vRef).dot(n);
        return approach > 0.0 ? gpic::Vector2(v - approach * n) : v;
    }
};

GPIC_REGISTER(gpic::ContactLaw<2>, FreeSlipLaw, "freeSlip")

} // namespace scenePlugin
