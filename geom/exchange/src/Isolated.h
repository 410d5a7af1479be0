#pragma once
// Work run in a child process, so that what it meets cannot harm the caller (private to
// geom_exchange).

#include <cstddef>
#include <functional>
#include <string>

namespace geom::exchange {

/// Runs `work` in a forked child whose further memory is limited to `memoryBytes` and whose
/// time to `seconds`, and returns what it returned. OpenCASCADE's readers can crash, loop or
/// exhaust memory on a corrupt file: such a child is stopped and reported as ExchangeError(file,
/// ...). An exception `work` throws comes back as ExchangeError with its message (an
/// ExchangeError's reason as it is).
std::string runIsolated(const std::function<std::string()>& work, const std::string& file,
                        std::size_t memoryBytes, int seconds);

}  // namespace geom::exchange
