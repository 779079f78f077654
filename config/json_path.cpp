#include "config/json_path.hpp"

#include "config/config.hpp"

namespace slmp::config {

void JsonAt::fail(std::string_view problem, std::string_view fix) const {
    throw ConfigError(source_ + ": " + (pointer_.empty() ? "/" : pointer_) + ": " + std::string(problem) + "; " +
                      std::string(fix));
}

bool JsonAt::has(std::string_view key) const { return value_.is_object() && value_.contains(key); }

JsonAt JsonAt::operator[](std::string_view key) const {
    expect_object();
    if (!value_.contains(key)) fail("missing key '" + std::string(key) + "'", "add it");
    return JsonAt(value_.at(std::string(key)), source_, pointer_ + "/" + std::string(key));
}

JsonAt JsonAt::operator[](std::size_t index) const {
    return JsonAt(value_.at(index), source_, pointer_ + "/" + std::to_string(index));
}

void JsonAt::expect_object() const {
    if (!value_.is_object()) fail("expected an object, found " + std::string(value_.type_name()), "write { ... }");
}

void JsonAt::expect_array() const {
    if (!value_.is_array()) fail("expected an array, found " + std::string(value_.type_name()), "write [ ... ]");
}

void JsonAt::only_keys(std::initializer_list<std::string_view> known) const {
    only_keys(std::span<const std::string_view>(known.begin(), known.size()));
}

void JsonAt::only_keys(std::span<const std::string_view> known) const {
    expect_object();
    for (const auto& [key, _] : value_.items()) {
        bool ok = false;
        for (auto k : known) ok = ok || k == key;
        if (ok) continue;
        std::string list;
        for (auto k : known) list += (list.empty() ? "" : ", ") + std::string(k);
        JsonAt(value_[key], source_, pointer_ + "/" + key).fail("unknown key", "use one of: " + list);
    }
}

std::string JsonAt::string() const {
    if (!value_.is_string()) fail("expected a string, found " + std::string(value_.type_name()), "quote the value");
    return value_.get<std::string>();
}

bool JsonAt::boolean() const {
    if (!value_.is_boolean()) fail("expected true or false, found " + std::string(value_.type_name()), "write true or false");
    return value_.get<bool>();
}

std::uint64_t JsonAt::unsigned_int(std::uint64_t max) const {
    if (!value_.is_number_unsigned() && !(value_.is_number_integer() && value_.get<std::int64_t>() >= 0))
        fail("expected a whole number from 0 to " + std::to_string(max) + ", found " + value_.dump(),
             "write a plain number such as 5000");
    auto v = value_.get<std::uint64_t>();
    if (v > max) fail("value " + std::to_string(v) + " is larger than " + std::to_string(max), "use a smaller number");
    return v;
}

std::uint16_t JsonAt::hex_code() const {
    auto text = string();
    bool ok = text.size() == 4 && text.find_first_not_of("0123456789ABCDEFabcdef") == std::string::npos;
    if (!ok) fail("'" + text + "' is not a 4-digit hexadecimal code", "write it like \"C059\"");
    return static_cast<std::uint16_t>(std::stoul(text, nullptr, 16));
}

nlohmann::json parse_json(const std::string& text, const std::string& source) {
    try {
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        throw ConfigError(source + ": not valid JSON (byte " + std::to_string(e.byte) + "): " + e.what() +
                          "; fix the syntax");
    } catch (const nlohmann::json::exception& e) {
        // Not only syntax: a number too large for a double ("1E400") is
        // out_of_range.406, and every mistake must reach the user as a ConfigError.
        throw ConfigError(source + ": not valid JSON: " + e.what() + "; write numbers that fit a double");
    }
}

}  // namespace slmp::config
