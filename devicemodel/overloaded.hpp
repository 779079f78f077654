// std::visit over a variant with one lambda per alternative:
//   std::visit(overloaded{[](const A&) {...}, [](const B&) {...}}, v);
#pragma once

namespace slmp::devicemodel {

template <class... Ts>
struct overloaded : Ts... {
    using Ts::operator()...;
};
// clang < 17 does not deduce aggregate template arguments (P1816); say it.
template <class... Ts>
overloaded(Ts...) -> overloaded<Ts...>;

}  // namespace slmp::devicemodel
