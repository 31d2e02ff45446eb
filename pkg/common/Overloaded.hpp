// The visitor of a std::variant made of one lambda per alternative.
#pragma once

namespace roundedmesh {

template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

}  // namespace roundedmesh
