// A JSON value together with where it came from (file and JSON pointer), so
// every configuration error can say "file: /ports/1/port: problem; fix".
#pragma once

#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace slmp::config {

class JsonAt {
public:
    JsonAt(const nlohmann::json& value, std::string source, std::string pointer = "")
        : value_(value), source_(std::move(source)), pointer_(std::move(pointer)) {}

    const nlohmann::json& json() const { return value_; }
    const std::string& pointer() const { return pointer_; }
    const std::string& source() const { return source_; }

    [[noreturn]] void fail(std::string_view problem, std::string_view fix) const;

    bool has(std::string_view key) const;
    JsonAt operator[](std::string_view key) const;        // required member
    JsonAt operator[](std::size_t index) const;           // array element

    void expect_object() const;
    void expect_array() const;
    // Every member must be one of `known`; an unknown key is usually a typo.
    void only_keys(std::initializer_list<std::string_view> known) const;
    void only_keys(std::span<const std::string_view> known) const;

    std::string string() const;
    bool boolean() const;
    std::uint64_t unsigned_int(std::uint64_t max) const;
    // A 16-bit code written as 4 hex digits, e.g. "C059" or "4801".
    std::uint16_t hex_code() const;

private:
    const nlohmann::json& value_;
    std::string source_;
    std::string pointer_;
};

// Parses JSON text, turning a syntax error into a ConfigError that names the source.
nlohmann::json parse_json(const std::string& text, const std::string& source);

}  // namespace slmp::config
