#include "particles/Particles.H"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace gpic {

void Particles::resize(std::size_t n)
{
    id.resize(n); body.resize(n); material.resize(n);
    x.resize(n, Vector2::Zero()); x0.resize(n, Vector2::Zero()); v.resize(n, Vector2::Zero());
    m.resize(n, 0.0); V.resize(n, 0.0); halfSize.resize(n, Vector2::Zero());
    sigma.resize(n, SymTensor::Zero()); eps.resize(n, SymTensor::Zero());
    epsP.resize(n, SymTensor::Zero());
    work.resize(n, 0.0);
    dEps.resize(n, SymTensor::Zero()); dOmega.resize(n, 0.0);
    for (auto& h : history_) h.resize(n, 0.0);
    if (affineOn_) {
        affine.resize(n, Eigen::Matrix2d::Zero());
        affineEnergy.resize(n, 0.0);
    }
    polar.resize(n);
}

void Particles::enableAffine()
{
    affineOn_ = true;
    affine.resize(size(), Eigen::Matrix2d::Zero());
    affineEnergy.resize(size(), 0.0);
}

void Particles::disableAffine()
{
    affineOn_ = false;
    decltype(affine)().swap(affine);
    std::vector<double>().swap(affineEnergy);
}

std::size_t Particles::add(const Vector2& position, double mass, double volume,
                           const Vector2& half, int bodyId, int materialId)
{
    const std::size_t i = size();
    resize(i + 1);
    id[i] = static_cast<int>(i);
    body[i] = bodyId;
    material[i] = materialId;
    x[i] = position;
    x0[i] = position;
    m[i] = mass;
    V[i] = volume;
    halfSize[i] = half;
    return i;
}

void Particles::declareHistory(const std::string& name)
{
    if (hasHistory(name)) return;
    historyNames_.push_back(name);
    history_.emplace_back(size(), 0.0);
}

bool Particles::hasHistory(const std::string& name) const
{
    return std::find(historyNames_.begin(), historyNames_.end(), name) != historyNames_.end();
}

std::vector<double>& Particles::history(const std::string& name)
{
    return const_cast<std::vector<double>&>(static_cast<const Particles&>(*this).history(name));
}

const std::vector<double>& Particles::history(const std::string& name) const
{
    auto it = std::find(historyNames_.begin(), historyNames_.end(), name);
    if (it == historyNames_.end())
        throw std::logic_error("particle history variable '" + name + "' was never declared");
    return history_[static_cast<std::size_t>(it - historyNames_.begin())];
}

namespace {
template <class V> void permute(V& a, const std::vector<std::size_t>& order)
{
    V sorted(order.size());
    for (std::size_t i = 0; i < order.size(); ++i) sorted[i] = a[order[i]];
    a.swap(sorted);
}
} // namespace

void Particles::sortByMaterial()
{
    std::vector<std::size_t> order(size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return material[a] < material[b]; });
    reorder(order);
}

void Particles::reorder(const std::vector<std::size_t>& order)
{
    permute(id, order); permute(body, order); permute(material, order);
    permute(x, order); permute(x0, order); permute(v, order);
    permute(m, order); permute(V, order); permute(halfSize, order);
    permute(sigma, order); permute(eps, order); permute(epsP, order); permute(work, order);
    permute(dEps, order); permute(dOmega, order);
    for (auto& h : history_) permute(h, order);
    if (affineOn_) {
        permute(affine, order);
        permute(affineEnergy, order);
    }
    polar.reorder(order);
}

std::vector<ParticleBlock> Particles::blocks() const
{
    std::vector<ParticleBlock> runs;
    for (std::size_t i = 0; i < size(); ++i) {
        if (runs.empty() || runs.back().material != material[i])
            runs.push_back({i, i + 1, material[i]});
        else
            runs.back().end = i + 1;
    }
    return runs;
}

namespace {
template<class V>
std::size_t held(const V& a)
{
    return a.capacity() * sizeof(typename V::value_type);
}
} // namespace

std::size_t Particles::bytes() const
{
    std::size_t total = held(id) + held(body) + held(material) + held(x) + held(x0) + held(v) + held(m) +
                        held(V) + held(halfSize) + held(sigma) + held(eps) + held(epsP) + held(work) +
                        held(dEps) + held(dOmega);
    for (const auto& h : history_) total += held(h);
    return total + held(affine) + held(affineEnergy) + polar.bytes();
}

} // namespace gpic
