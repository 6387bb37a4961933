// FunctionRef: a non-owning reference to a callable (a lambda, a function).
//
// Graph traversals take their per-node callback through it: unlike
// std::function it never allocates, whatever the lambda captures, so a
// traversal run every step costs no heap allocation. The callable must
// outlive the call that receives the reference (pass lambdas directly).
#pragma once

#include <type_traits>
#include <utility>

namespace sinew {

template <class Signature>
class FunctionRef;

template <class R, class... Args>
class FunctionRef<R(Args...)> {
 public:
  FunctionRef() = default;
  template <class F>
    requires(!std::is_same_v<std::remove_cvref_t<F>, FunctionRef> && std::is_invocable_r_v<R, F&, Args...>)
  FunctionRef(F&& f)  // NOLINT: implicit, as a std::function parameter would be
      : object_(const_cast<void*>(static_cast<const void*>(&f))), call_([](void* o, Args... a) -> R {
          return (*static_cast<std::remove_reference_t<F>*>(o))(std::forward<Args>(a)...);
        }) {}

  R operator()(Args... a) const { return call_(object_, std::forward<Args>(a)...); }
  explicit operator bool() const { return call_ != nullptr; }

 private:
  void* object_ = nullptr;
  R (*call_)(void*, Args...) = nullptr;
};

}  // namespace sinew
