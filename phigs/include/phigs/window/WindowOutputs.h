#pragma once

#include "phigs/input/InputSource.h"
#include "phigs/vk/Context.h"
#include "phigs/ws/OutputRegistry.h"

namespace phigs {

/// Adds the Window type's output that opens its own GLFW window to `registry` (over
/// vk::registerOutputs' one, which it still uses when the connection's settings hold a window
/// the program made): the connection identifier is an X display name (empty: $DISPLAY), the
/// window has the connection's size (0: the type's display size) and follows its drawable.
/// Its Vulkan context is made from `context` with the window's surface extensions.
void registerWindowOutputs(OutputRegistry& registry, const vk::ContextSettings& context);

/// The input source (mouse, keys) of the window such an output opened itself, made at the first
/// call, or null for any other output: what a program that never sees the window (the C
/// binding) connects the workstation's devices to.
InputSource* ownWindowInputSource(WorkstationOutput* output);

}  // namespace phigs
