#pragma once

// One offscreen workstation with structure 1 posted: a test replaces the structure's elements
// and reads the draw list the workstation builds from them.

#include "phigs/Phigs.h"

#include <vector>

namespace phigs::test {

/// A PHIGS instance whose offscreen workstation 1 shows structure 1.
struct PostedScene {
    Phigs phigs;
    StructureStore* store = nullptr;
    Workstation* ws = nullptr;
    PostedScene() {
        phigs.open();
        store = &phigs.store();
        ws = &phigs.openWorkstation(1, WorkstationType::OffscreenImage);
        ws->postStructure(1, 0.5);
    }
    /// Structure 1 emptied and filled with `elements`; the workstation's new draw list.
    const DrawList& draw(const std::vector<Element>& elements) {
        store->openStructure(1);
        store->emptyStructure(1);
        for (const Element& e : elements) store->insert(e);
        store->closeStructure();
        return ws->display();
    }
};

}  // namespace phigs::test
