#pragma once

// One element inserted at the element pointer as function `fn`: the state first (error 5), then
// `make` checks the arguments and builds the element.

#include "Binding.h"

namespace phigs::c {

template <class Make>
void insertElement(int fn, Make&& make) {
    Binding::instance().call(fn, [&](Phigs& p) {
        const std::string name = functionName(fn);
        StructureStore& store = p.store();
        if (!store.isStructureOpen()) raise(&p.errorLog(), errors::NotStructureOpen, name.c_str());
        store.insert(make(name.c_str()));
    });
}

}  // namespace phigs::c
