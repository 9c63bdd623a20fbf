#include "particles/Particles.H"

#include "particles/ParticleFields.H"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <type_traits>
#include <variant>

namespace gpic {

namespace {

template <class T> T zero() { return T(0); }
template <> Vector2 zero<Vector2>() { return Vector2::Zero(); }
template <> SymTensor zero<SymTensor>() { return SymTensor::Zero(); }
template <> PlaneSpace::Gradient zero<PlaneSpace::Gradient>() { return PlaneSpace::Gradient::Zero(); }

template <class V> void permute(V& a, const std::vector<std::size_t>& order)
{
    V sorted(order.size());
    for (std::size_t i = 0; i < order.size(); ++i) sorted[i] = a[order[i]];
    a.swap(sorted);
}

template <class V> std::size_t held(const V& a) { return a.capacity() * sizeof(typename V::value_type); }

template <class V> void resizeZero(V& a, std::size_t n) { a.resize(n, zero<typename V::value_type>()); }

//- Apply op to every array of a group that p carries (the derived outputs have none).
template <class Op> void forCarried(const Particles& p, Op op)
{
    for (const ParticleField& f : particleFields())
        if (f.array && p.carries(f.group)) std::visit(op, fieldArray(f, p));
}

} // namespace

void Particles::resize(std::size_t n)
{
    forCarried(*this, [n](auto* a) { resizeZero(*a, n); });
    for (auto& h : history_) h.resize(n, 0.0);
}

void Particles::carry(FieldGroup g)
{
    carried_[static_cast<int>(g)] = true;
    const std::size_t n = size();
    for (const ParticleField& f : particleFields())
        if (f.array && f.group == g) std::visit([n](auto* a) { resizeZero(*a, n); }, f.array(*this));
}

void Particles::drop(FieldGroup g)
{
    if (g == FieldGroup::core) throw std::logic_error("the core particle arrays cannot be dropped");
    carried_[static_cast<int>(g)] = false;
    for (const ParticleField& f : particleFields())
        if (f.array && f.group == g) std::visit([](auto* a) { std::decay_t<decltype(*a)>().swap(*a); }, f.array(*this));
}

void Particles::append(const Particles& other)
{
    const std::size_t n0 = size();
    for (const auto& h : other.historyNames()) declareHistory(h);
    for (const ParticleField& f : particleFields())
        if (other.carries(f.group)) carry(f.group);
    resize(n0 + other.size());
    const auto at = static_cast<std::ptrdiff_t>(n0);
    for (const ParticleField& f : particleFields()) {
        if (!f.array || !other.carries(f.group)) continue;
        std::visit(
            [&](auto* to) {
                const auto* from = std::get<std::decay_t<decltype(to)>>(fieldArray(f, other));
                std::copy(from->begin(), from->end(), to->begin() + at);
            },
            f.array(*this));
    }
    for (const auto& h : other.historyNames())
        std::copy(other.history(h).begin(), other.history(h).end(), history(h).begin() + at);
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
    forCarried(*this, [&](auto* a) { permute(*a, order); });
    for (auto& h : history_) permute(h, order);
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

std::size_t Particles::bytes() const
{
    std::size_t total = 0;
    forCarried(*this, [&](const auto* a) { total += held(*a); });
    for (const auto& h : history_) total += held(h);
    return total;
}

} // namespace gpic
