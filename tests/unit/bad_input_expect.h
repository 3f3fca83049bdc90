#pragma once
// The assertion every bad-input table row makes: loading failed with exactly one line that starts
// with the file's path and names the problem.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace candela::test {

inline void expectOneLineErrorNamingFile(const std::filesystem::path& path, const std::string& message,
                                         const std::string& fragment) {
    ASSERT_FALSE(message.empty()) << "loaded without error";
    EXPECT_EQ(message.rfind(path.string() + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(fragment), std::string::npos) << "message: " << message << "\nexpected fragment: " << fragment;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

}  // namespace candela::test
