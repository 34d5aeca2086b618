#pragma once
// An object of a bound class made by __new__ without __init__ (as a stateless pickle makes one
// before __setstate__) holds no C++ value: pybind11 would hand its methods uninitialised memory
// (it allocates the value lazily for __init__ to construct in place) and they crash. Every
// class the module binds converts through this caster instead, which refuses such an object
// with a TypeError naming the class, before pybind11 touches it. __init__ and __setstate__
// construct through the value's holder directly, not through the caster, so they still work.
// LINKWRIGHT_PYTHON_REFUSE_UNINITIALISED(Type, "Name") must follow Type's definition and come
// before any binding of it, in every file that binds or converts it.

#include <pybind11/pybind11.h>

#include <string>

namespace linkwright::python {

template <typename T>
class InitialisedCaster : public pybind11::detail::type_caster_base<T> {
public:
  bool load(pybind11::handle src, bool convert) {
    const pybind11::detail::type_info* info = this->typeinfo;
    if (info != nullptr && src && PyObject_TypeCheck(src.ptr(), info->type)) {
      auto* inst = reinterpret_cast<pybind11::detail::instance*>(src.ptr());
      const auto holder = inst->get_value_and_holder(info, false);
      if (holder.inst != nullptr && !holder.holder_constructed()) {  // its value pointer is null then
        const std::string type =
            pybind11::str(pybind11::handle(reinterpret_cast<PyObject*>(info->type)).attr("__name__"));
        throw pybind11::type_error("linkwright." + type + " is not initialised: it was made by " + type +
                                   ".__new__ without __init__ (make one with linkwright." + type +
                                   "(...), or unpickle one)");
      }
    }
    return pybind11::detail::type_caster_base<T>::load(src, convert);
  }
};

}  // namespace linkwright::python

#define LINKWRIGHT_PYTHON_REFUSE_UNINITIALISED(Type)                                 \
  namespace pybind11::detail {                                                       \
  template <>                                                                        \
  class type_caster<Type> : public ::linkwright::python::InitialisedCaster<Type> {}; \
  }
