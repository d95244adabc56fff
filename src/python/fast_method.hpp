// Methods of a pybind11 class made as CPython's own functions, for the calls a learner's loop
// makes millions of times.
//
// pybind11's dispatch costs some 1,800 instructions a call (its overload loop, casting each
// argument, finding the instance's C++ object by its type's hash) and gives a function whose
// signature inspect cannot read. A cheap shot's step costs some 55,000 instructions in C++, and a
// one-shot episode is a step and a reset: two dispatches are a quarter of Python's share of it.
// CPython calls a METH_O or METH_FASTCALL function in a method descriptor directly, and reads its
// signature from the first line of its doc ("name($self, /, ...)\n--\n\n").
#pragma once

#include <pybind11/pybind11.h>

#include <string>
#include <typeinfo>

namespace cue_sim
{
namespace python
{
/// The C++ object of `self`, an instance of the pybind11 class of T (or of a Python subclass): a
/// TypeError when its __init__ has not run.
template <typename T>
T& instanceOf(PyObject* self)
{
  static const pybind11::detail::type_info* const type = pybind11::detail::get_type_info(typeid(T));
  auto* inst = reinterpret_cast<pybind11::detail::instance*>(self);
  pybind11::detail::value_and_holder v = inst->get_value_and_holder(type, false);
  if (!v || !v.holder_constructed())
    throw pybind11::type_error(std::string(Py_TYPE(self)->tp_name) + ": the object was not initialised");
  return *static_cast<T*>(v.value_ptr());
}

/// Sets Python's error from the C++ exception being handled, as pybind11's dispatch would: an
/// error_already_set restored, anything else through the module's exception translators.
inline void setPythonError()
{
  try
  {
    throw;
  }
  catch (pybind11::error_already_set& e)
  {
    e.restore();
  }
  catch (...)
  {
    namespace detail = pybind11::detail;
    if (detail::apply_exception_translators(detail::get_local_internals().registered_exception_translators))
      return;
    if (detail::apply_exception_translators(detail::get_internals().registered_exception_translators))
      return;
    PyErr_SetString(PyExc_SystemError, "an exception escaped cue_sim's exception translators");
  }
}

/// Adds `def` (static storage: the descriptor keeps a pointer to it) to the class `cls` as a method.
inline void addFastMethod(const pybind11::handle& cls, PyMethodDef& def)
{
  auto descriptor = pybind11::reinterpret_steal<pybind11::object>(
      PyDescr_NewMethod(reinterpret_cast<PyTypeObject*>(cls.ptr()), &def));
  if (!descriptor)
    throw pybind11::error_already_set();
  pybind11::setattr(cls, def.ml_name, descriptor);
}

/// The GIL released for a scope when `release` (else kept), by CPython's own calls: pybind11's
/// gil_scoped_release also keeps its thread state in thread-local storage for a gil_scoped_acquire
/// inside, which the code inside these scopes (C++ only) never makes.
class ReleasedGil
{
public:
  explicit ReleasedGil(bool release = true) : state_(release ? PyEval_SaveThread() : nullptr) {}
  ~ReleasedGil()
  {
    if (state_)
      PyEval_RestoreThread(state_);
  }
  ReleasedGil(const ReleasedGil&) = delete;
  ReleasedGil& operator=(const ReleasedGil&) = delete;

private:
  PyThreadState* state_;
};

}  // namespace python
}  // namespace cue_sim
