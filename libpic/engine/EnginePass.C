#include "engine/EnginePass.H"

#include <algorithm>

namespace gpic {

std::vector<std::unique_ptr<EnginePass>> assemblePasses(PassScene& scene)
{
    std::vector<std::unique_ptr<EnginePass>> passes;
    // The table is ordered by name, and the sort is stable: equal ranks keep that order.
    for (const auto& [name, entry] : Registry<EnginePass>::table())
        if (auto pass = entry.factory(scene)) passes.push_back(std::move(pass));
    std::stable_sort(passes.begin(), passes.end(),
                     [](const auto& a, const auto& b) { return a->rank() < b->rank(); });
    return passes;
}

} // namespace gpic
