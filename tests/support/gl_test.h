// Headless GL tests: one debug context per test process, and every KHR_debug
// error or high-severity message raised during a test fails that test.
#pragma once

#include "swell/gl/context.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace swell::test {

class GlTest : public ::testing::Test {
public:
    // Messages seen since the test began (errors fail it on tear-down).
    static std::vector<gl::DebugMessage>& messages();
    // Installs the fixture's handler again, after a test installed its own.
    static void restoreDebugHandler();

protected:
    static void SetUpTestSuite();
    void SetUp() override;
    void TearDown() override;
};

} // namespace swell::test
