#include "particles/CosseratParticles.H"

namespace gpic {

namespace {
template <class T> void permute(std::vector<T>& a, const std::vector<std::size_t>& order)
{
    std::vector<T> sorted(order.size());
    for (std::size_t i = 0; i < order.size(); ++i) sorted[i] = a[order[i]];
    a.swap(sorted);
}

template <class T> std::size_t held(const std::vector<T>& a) { return a.capacity() * sizeof(T); }
} // namespace

void CosseratParticles::enable(std::size_t n)
{
    enabled_ = true;
    resize(n);
}

void CosseratParticles::disable()
{
    enabled_ = false;
    std::vector<double>().swap(w);
    std::vector<double>().swap(omega);
    std::vector<double>().swap(sigma21);
    std::vector<Vector2>().swap(mu);
    std::vector<Vector2>().swap(kappa);
    std::vector<double>().swap(dRotation);
    std::vector<Vector2>().swap(dKappa);
}

void CosseratParticles::resize(std::size_t n)
{
    if (!enabled_) return;
    w.resize(n, 0.0);
    omega.resize(n, 0.0);
    sigma21.resize(n, 0.0);
    mu.resize(n, Vector2::Zero());
    kappa.resize(n, Vector2::Zero());
    dRotation.resize(n, 0.0);
    dKappa.resize(n, Vector2::Zero());
}

void CosseratParticles::reorder(const std::vector<std::size_t>& order)
{
    if (!enabled_) return;
    permute(w, order); permute(omega, order); permute(sigma21, order);
    permute(mu, order); permute(kappa, order);
    permute(dRotation, order); permute(dKappa, order);
}

std::size_t CosseratParticles::bytes() const
{
    return held(w) + held(omega) + held(sigma21) + held(mu) + held(kappa) + held(dRotation) + held(dKappa);
}

} // namespace gpic
