#pragma once
// A non-owning reference to a callable, for per-packet and per-lap callbacks: no allocation and no
// std::function copy. The referenced callable must outlive the call it is passed to.
#include <type_traits>
#include <utility>

namespace ydscope {

template <class Signature>
class FunctionRef;

template <class R, class... Args>
class FunctionRef<R(Args...)> {
 public:
  template <class F>
  requires(!std::is_same_v<std::remove_cvref_t<F>, FunctionRef> && std::is_invocable_r_v<R, F&, Args...>)
      // Implicit, as it is passed inline like a lambda; the requires clause keeps FunctionRef itself
      // out, which clang-tidy 14 does not read.
      FunctionRef(F&& f)  // NOLINT(google-explicit-constructor, bugprone-forwarding-reference-overload)
      : object_(const_cast<void*>(static_cast<const void*>(&f))), call_([](void* object, Args... args) -> R {
          return (*static_cast<std::remove_reference_t<F>*>(object))(std::forward<Args>(args)...);
        }) {}

  R operator()(Args... args) const { return call_(object_, std::forward<Args>(args)...); }

 private:
  void* object_;
  R (*call_)(void*, Args...);
};

}  // namespace ydscope
