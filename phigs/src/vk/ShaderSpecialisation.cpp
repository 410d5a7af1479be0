#include "ShaderSpecialisation.h"

#include "phigs/vk/ShaderCache.h"

#include <spirv-tools/libspirv.h>
#include <spirv-tools/optimizer.hpp>

#include <algorithm>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

// Why on the CPU: on lavapipe (Mesa 22.3) code that a specialisation constant makes dead still
// cost time, measured: a never-taken discard block and reads of varyings nothing uses made the
// benchmark frame up to 0.3x of the baseline slower each. Freezing the constants, letting
// SPIRV-Tools remove the dead code and the unread inputs, and then the vertex work that fed only
// those, took the benchmark scene from 2.0x to about 1.3x the baseline's frame time. Other
// drivers just get a smaller module.

namespace phigs::vk {
namespace {

constexpr std::uint32_t kBuiltInPosition = 0;
constexpr std::uint32_t kBuiltInPointSize = 1;

// The locations of the Input variables an entry point lists (after the unused ones are removed),
// read from the module's instruction stream.
std::vector<std::uint32_t> inputLocations(const std::vector<std::uint32_t>& module) {
    constexpr std::uint32_t kOpEntryPoint = 15, kOpVariable = 59, kOpDecorate = 71;
    constexpr std::uint32_t kDecorationLocation = 30, kStorageClassInput = 1;
    std::unordered_set<std::uint32_t> interface, inputs;
    std::unordered_map<std::uint32_t, std::uint32_t> locations;
    for (std::size_t i = 5; i < module.size();) {
        const std::uint32_t count = module[i] >> 16, opcode = module[i] & 0xffff;
        if (count == 0 || i + count > module.size())
            throw std::runtime_error("specialised SPIR-V is malformed");
        if (opcode == kOpEntryPoint) {
            // Execution model, function id, literal name (nul-terminated, padded), interface ids.
            std::size_t w = i + 3;
            while (w < i + count && (module[w] >> 24) != 0) ++w;
            for (++w; w < i + count; ++w) interface.insert(module[w]);
        } else if (opcode == kOpVariable && count >= 4 && module[i + 3] == kStorageClassInput) {
            inputs.insert(module[i + 2]);
        } else if (opcode == kOpDecorate && count >= 4 && module[i + 2] == kDecorationLocation) {
            locations[module[i + 1]] = module[i + 3];
        }
        i += count;
    }
    std::vector<std::uint32_t> result;
    for (std::uint32_t id : interface)
        if (inputs.count(id) && locations.count(id)) result.push_back(locations[id]);
    std::sort(result.begin(), result.end());
    return result;
}

std::vector<std::uint32_t> run(spvtools::Optimizer& optimizer, std::span<const std::uint32_t> words,
                               const char* stage) {
    std::string messages;
    optimizer.SetMessageConsumer(
        [&](spv_message_level_t level, const char*, const spv_position_t&, const char* message) {
            if (level <= SPV_MSG_ERROR) messages += std::string(message) + "; ";
        });
    std::vector<std::uint32_t> result;
    // The input is the build's own glslang output (and the validation layer checks what the driver
    // gets): validating it again took about a third of the specialisation's time.
    spvtools::OptimizerOptions options;
    options.set_run_validator(false);
    if (!optimizer.Run(words.data(), words.size(), &result, options))
        throw std::runtime_error(std::string("specialising the ") + stage + " shader failed: " + messages);
    return result;
}

void freezeConstants(spvtools::Optimizer& optimizer, std::span<const SpecialisationValue> values) {
    std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> defaults;
    for (const SpecialisationValue& v : values) defaults[v.id] = {std::uint32_t(v.value)};
    optimizer.RegisterPass(spvtools::CreateSetSpecConstantDefaultValuePass(defaults))
        .RegisterPass(spvtools::CreateFreezeSpecConstantValuePass())
        .RegisterPass(spvtools::CreateFoldSpecConstantOpAndCompositePass())
        .RegisterPerformancePasses();
}

void registerFragmentPasses(spvtools::Optimizer& optimizer, std::span<const SpecialisationValue> values) {
    freezeConstants(optimizer, values);
    optimizer.RegisterPass(spvtools::CreateRemoveUnusedInterfaceVariablesPass());
}

/// The passes for the vertex stage, keeping only the outputs in the two sets (they are read when
/// the optimizer runs, not now).
void registerVertexPasses(spvtools::Optimizer& optimizer, std::span<const SpecialisationValue> values,
                          std::unordered_set<std::uint32_t>& liveLocations,
                          std::unordered_set<std::uint32_t>& liveBuiltins) {
    freezeConstants(optimizer, values);
    optimizer.RegisterPass(spvtools::CreateEliminateDeadOutputStoresPass(&liveLocations, &liveBuiltins))
        .RegisterPass(spvtools::CreateAggressiveDCEPass())
        .RegisterPass(spvtools::CreateRemoveUnusedInterfaceVariablesPass());
}

}  // namespace

SpecialisedStages specialiseUncached(std::span<const std::uint32_t> vertex,
                                     std::span<const std::uint32_t> fragment,
                                     std::span<const SpecialisationValue> values);

namespace {

/// What the passes make of their input depends on SPIRV-Tools' version and on the passes: the
/// tag names both (the list of passes as registered), so a change to either turns the disk
/// cache's files into misses. The format number covers changes to the words of cacheInput.
std::string cacheTag() {
    std::string tag = std::string("phigs specialise 1; ") + spvSoftwareVersionDetailsString();
    std::unordered_set<std::uint32_t> noLocations, noBuiltins;
    spvtools::Optimizer fragment(SPV_ENV_VULKAN_1_1), vertex(SPV_ENV_VULKAN_1_1);
    registerFragmentPasses(fragment, {});
    registerVertexPasses(vertex, {}, noLocations, noBuiltins);
    for (const spvtools::Optimizer* optimizer : {&fragment, &vertex}) {
        tag += ";";
        for (const char* name : optimizer->GetPassNames()) tag += std::string(" ") + name;
    }
    return tag;
}

/// The inputs as one word sequence for the disk cache: each part's length, then the part.
std::vector<std::uint32_t> cacheInput(std::span<const std::uint32_t> vertex,
                                      std::span<const std::uint32_t> fragment,
                                      std::span<const SpecialisationValue> values) {
    std::vector<std::uint32_t> input;
    input.reserve(vertex.size() + fragment.size() + 2 * values.size() + 3);
    input.push_back(std::uint32_t(vertex.size()));
    input.insert(input.end(), vertex.begin(), vertex.end());
    input.push_back(std::uint32_t(fragment.size()));
    input.insert(input.end(), fragment.begin(), fragment.end());
    input.push_back(std::uint32_t(values.size()));
    for (const SpecialisationValue& v : values)
        input.push_back(v.id), input.push_back(std::uint32_t(v.value));
    return input;
}

/// The pair from the disk cache (PHIGS_SHADER_CACHE), or specialised and stored there.
SpecialisedStages specialiseThroughDisk(std::span<const std::uint32_t> vertex,
                                        std::span<const std::uint32_t> fragment,
                                        std::span<const SpecialisationValue> values) {
    static const ShaderCache disk = ShaderCache::fromEnvironment();
    static const std::string tag = cacheTag();
    if (!disk.enabled()) return specialiseUncached(vertex, fragment, values);
    const std::vector<std::uint32_t> input = cacheInput(vertex, fragment, values);
    if (auto pair = disk.load(input, tag)) {
        try {
            SpecialisedStages out;
            out.vertexInputLocations = inputLocations(pair->vertex);
            inputLocations(pair->fragment);  // throws when its instructions do not add up
            out.vertex = std::move(pair->vertex);
            out.fragment = std::move(pair->fragment);
            return out;
        } catch (const std::runtime_error&) {
            // Malformed although its checksum matched: specialised again and stored over it.
        }
    }
    SpecialisedStages out = specialiseUncached(vertex, fragment, values);
    disk.store(input, tag, {out.vertex, out.fragment});
    return out;
}

}  // namespace

SpecialisedStages specialiseStages(std::span<const std::uint32_t> vertex,
                                   std::span<const std::uint32_t> fragment,
                                   std::span<const SpecialisationValue> values) {
    // SPIRV-Tools takes tens of milliseconds a pair; every renderer of the process (offscreen,
    // window, hardcopy, each workstation, each test) asks for the same few pairs, so each is
    // specialised once, and once for all processes where the disk cache is on. Keyed by the
    // code's contents, not its address.
    using Key = std::tuple<std::vector<std::uint32_t>, std::vector<std::uint32_t>,
                           std::vector<std::pair<std::uint32_t, std::int32_t>>>;
    static std::mutex mutex;
    static std::map<Key, SpecialisedStages> cache;
    Key key{{vertex.begin(), vertex.end()}, {fragment.begin(), fragment.end()}, {}};
    for (const SpecialisationValue& v : values) std::get<2>(key).emplace_back(v.id, v.value);
    {
        std::lock_guard lock(mutex);
        if (auto it = cache.find(key); it != cache.end()) return it->second;
    }
    SpecialisedStages out = specialiseThroughDisk(vertex, fragment, values);
    std::lock_guard lock(mutex);
    return cache.emplace(std::move(key), std::move(out)).first->second;
}

SpecialisedStages specialiseUncached(std::span<const std::uint32_t> vertex,
                                     std::span<const std::uint32_t> fragment,
                                     std::span<const SpecialisationValue> values) {
    SpecialisedStages out;
    std::unordered_set<std::uint32_t> liveLocations, liveBuiltins;
    {
        spvtools::Optimizer optimizer(SPV_ENV_VULKAN_1_1);
        registerFragmentPasses(optimizer, values);
        out.fragment = run(optimizer, fragment, "fragment");
    }
    {
        // The vertex outputs that live are the inputs the specialised fragment shader still lists.
        for (std::uint32_t location : inputLocations(out.fragment)) liveLocations.insert(location);
        // The rasteriser, not the fragment shader, reads these.
        liveBuiltins.insert({kBuiltInPosition, kBuiltInPointSize});
        spvtools::Optimizer optimizer(SPV_ENV_VULKAN_1_1);
        registerVertexPasses(optimizer, values, liveLocations, liveBuiltins);
        out.vertex = run(optimizer, vertex, "vertex");
    }
    out.vertexInputLocations = inputLocations(out.vertex);
    return out;
}

}  // namespace phigs::vk
