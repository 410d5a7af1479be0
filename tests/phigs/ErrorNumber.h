#pragma once

// The PHIGS error number a call raises (0 when it raises none), for the tests' error cases.

#include "phigs/core/Error.h"

namespace phigs::test {

template <class F>
int errorOf(F&& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.number();
    }
    return 0;
}

}  // namespace phigs::test
