// Runs something that must refuse its input, and hands back the refusal.
#pragma once

#include "swell/error.h"

#include <gtest/gtest.h>

namespace swell::test {

// The swell::InputError `load` throws; fails the test when it throws none.
template <class F>
InputError expectInputError(F load)
{
    try {
        load();
    } catch (const InputError& e) {
        return e;
    }
    ADD_FAILURE() << "no InputError";
    return InputError({}, "");
}

} // namespace swell::test
