#include "frontends/hostlink/record.hpp"

#include <algorithm>

#include "devicemodel/hex.hpp"

namespace slmp::hostlink {

std::string fcs(std::string_view text) {
    unsigned x = 0;
    for (char c : text) x ^= static_cast<unsigned char>(c);
    return devicemodel::hex2(static_cast<std::uint8_t>(x));
}

std::string csm(std::string_view text) {
    unsigned sum = 0;
    for (char c : text) sum -= static_cast<unsigned char>(c);
    return devicemodel::hex2(static_cast<std::uint8_t>(sum));
}

std::string close_record(std::string_view body) {
    std::string record(body);
    record += fcs(body);
    record += "*\r";
    return record;
}

Cut cut_record(std::span<const std::uint8_t> stream, std::size_t limit) {
    Cut cut;
    if (stream.empty()) return cut;
    auto start = std::find_if(stream.begin(), stream.end(), [](std::uint8_t b) { return b == '@' || b == kStx; });
    if (start != stream.begin()) {
        cut.kind = Cut::Kind::Garbage;
        cut.consumed = static_cast<std::size_t>(start - stream.begin());
        return cut;
    }
    bool wrapped = stream[0] == kStx;
    std::size_t at = wrapped ? 1 : 0;
    if (wrapped) {
        if (stream.size() < 2) return cut;
        if (stream[1] != '@') {   // STX not followed by a record: drop the STX alone
            cut.kind = Cut::Kind::Garbage;
            cut.consumed = 1;
            return cut;
        }
    }
    auto cr = std::find(stream.begin() + static_cast<std::ptrdiff_t>(at), stream.end(), std::uint8_t{'\r'});
    if (cr == stream.end()) {
        if (stream.size() >= limit) {
            cut.kind = Cut::Kind::Garbage;
            cut.consumed = stream.size();
        }
        return cut;
    }
    std::size_t end = static_cast<std::size_t>(cr - stream.begin()) + 1;   // one past the CR
    if (wrapped) {
        if (end == stream.size()) return cut;   // the ETX may still come
        if (stream[end] == kEtx) ++end;        // a missing ETX is forgiven: the record is whole
    }
    cut.kind = Cut::Kind::Record;
    cut.consumed = end;
    cut.wrapped = wrapped;
    auto first = reinterpret_cast<const char*>(stream.data()) + at;
    auto last = reinterpret_cast<const char*>(stream.data()) + static_cast<std::ptrdiff_t>(cr - stream.begin()) + 1;
    cut.record = std::string_view(first, static_cast<std::size_t>(last - first));
    return cut;
}

}  // namespace slmp::hostlink
