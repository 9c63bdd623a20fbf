#include "engine/EnginePass.H"

#include <algorithm>

namespace gpic {

template <int D>
std::vector<std::unique_ptr<EnginePass<D>>> assemblePasses(PassScene<D>& scene)
{
    std::vector<std::unique_ptr<EnginePass<D>>> passes;
    // The table is ordered by name, and the sort is stable: equal ranks keep that order.
    for (const auto& [name, entry] : Registry<EnginePass<D>>::table())
        if (auto pass = entry.factory(scene)) passes.push_back(std::move(pass));
    std::stable_sort(passes.begin(), passes.end(),
                     [](const auto& a, const auto& b) { return a->rank() < b->rank(); });
    return passes;
}

template std::vector<std::unique_ptr<EnginePass<2>>> assemblePasses(PassScene<2>&);
#if GPIC_WITH_3D
template std::vector<std::unique_ptr<EnginePass<3>>> assemblePasses(PassScene<3>&);
#endif
} // namespace gpic
