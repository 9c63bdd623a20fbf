#include "particles/Particles.H"

#include "particles/ParticleFields.H"

#include "core/ByteSize.H"
#include "core/error.H"

#include <algorithm>
#include <new>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <type_traits>
#include <variant>

namespace gpic {

namespace {

template <class T> T zero()
{
    if constexpr (std::is_arithmetic_v<T>)
        return T(0);
    else
        return T::Zero();
}

template <class V> void permute(V& a, const std::vector<std::size_t>& order)
{
    V sorted(order.size());
    for (std::size_t i = 0; i < order.size(); ++i) sorted[i] = a[order[i]];
    a.swap(sorted);
}

template <class V> std::size_t held(const V& a) { return a.capacity() * sizeof(typename V::value_type); }

template <class V> void resizeZero(V& a, std::size_t n) { a.resize(n, zero<typename V::value_type>()); }

//- Apply op to every array of a group that p carries (the derived outputs have none).
template <int D, class Op> void forCarried(const Particles<D>& p, Op op)
{
    for (const ParticleField<D>& f : particleFields<D>())
        if (f.array && p.carries(f.group)) std::visit(op, fieldArray(f, p));
}

} // namespace

template <int D> void Particles<D>::resize(std::size_t n)
{
    try {
        forCarried(*this, [n](auto* a) { resizeZero(*a, n); });
        for (auto& h : history_) h.resize(n, 0.0);
    } catch (const std::bad_alloc&) {
        // What the arrays of n particles take, in one line instead of a bare bad_alloc.
        double each = static_cast<double>(history_.size() * sizeof(double));
        forCarried(*this, [&each](const auto* a) {
            each += sizeof(typename std::decay_t<decltype(*a)>::value_type);
        });
        std::ostringstream msg;
        msg << "out of memory: the particle arrays of " << n << " particles need " << byteSize(each * static_cast<double>(n))
            << ", more than this process may have (ulimit -v)";
        throw RunError(msg.str());
    }
}

template <int D> void Particles<D>::carry(FieldGroup g)
{
    carried_[static_cast<int>(g)] = true;
    const std::size_t n = size();
    for (const ParticleField<D>& f : particleFields<D>())
        if (f.array && f.group == g) std::visit([n](auto* a) { resizeZero(*a, n); }, f.array(*this));
}

template <int D> void Particles<D>::drop(FieldGroup g)
{
    if (g == FieldGroup::core) throw std::logic_error("the core particle arrays cannot be dropped");
    carried_[static_cast<int>(g)] = false;
    for (const ParticleField<D>& f : particleFields<D>())
        if (f.array && f.group == g) std::visit([](auto* a) { std::decay_t<decltype(*a)>().swap(*a); }, f.array(*this));
}

template <int D> void Particles<D>::append(const Particles<D>& other)
{
    const std::size_t n0 = size();
    for (const auto& h : other.historyNames()) declareHistory(h);
    for (const ParticleField<D>& f : particleFields<D>())
        if (other.carries(f.group)) carry(f.group);
    resize(n0 + other.size());
    const auto at = static_cast<std::ptrdiff_t>(n0);
    for (const ParticleField<D>& f : particleFields<D>()) {
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

template <int D> std::size_t Particles<D>::add(const Vector& position, double mass, double volume, const Vector& half, int bodyId,
                              int materialId)
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

template <int D> void Particles<D>::declareHistory(const std::string& name)
{
    if (hasHistory(name)) return;
    historyNames_.push_back(name);
    history_.emplace_back(size(), 0.0);
}

template <int D> bool Particles<D>::hasHistory(const std::string& name) const
{
    return std::find(historyNames_.begin(), historyNames_.end(), name) != historyNames_.end();
}

template <int D> std::vector<double>& Particles<D>::history(const std::string& name)
{
    return const_cast<std::vector<double>&>(static_cast<const Particles<D>&>(*this).history(name));
}

template <int D> const std::vector<double>& Particles<D>::history(const std::string& name) const
{
    auto it = std::find(historyNames_.begin(), historyNames_.end(), name);
    if (it == historyNames_.end())
        throw std::logic_error("particle history variable '" + name + "' was never declared");
    return history_[static_cast<std::size_t>(it - historyNames_.begin())];
}

template <int D> void Particles<D>::sortByMaterial()
{
    std::vector<std::size_t> order(size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return material[a] < material[b]; });
    reorder(order);
}

template <int D> void Particles<D>::reorder(const std::vector<std::size_t>& order)
{
    forCarried(*this, [&](auto* a) { permute(*a, order); });
    for (auto& h : history_) permute(h, order);
}

template <int D> std::vector<ParticleBlock> Particles<D>::blocks() const
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

template <int D> std::size_t Particles<D>::bytes() const
{
    std::size_t total = 0;
    forCarried(*this, [&](const auto* a) { total += held(*a); });
    for (const auto& h : history_) total += held(h);
    return total;
}

template class Particles<2>;
#if GPIC_WITH_3D
template class Particles<3>;
#endif

} // namespace gpic
