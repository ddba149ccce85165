// Kernel arguments set from typed values in the order the kernel declares its parameters, so
// that no argument index is ever written by hand (docs/architecture.md, Kernel arguments).
//
// A KernelSignature<Params...> names a kernel and its parameters; TypedKernel<Signature>
// creates that kernel from any program and binds it from exactly one value of each of
// Params, in order: a missing, extra or differently typed value is a compile error. A
// parameter type with a `for_each_arg(visit)` member (an argument group, such as the seven
// scene parameters every tracing kernel takes) stands for the several parameters it visits.
// The names serve the test that compares every signature with the kernel's own parameter
// list (tests/device/kernel_signatures_test.cpp).
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "device/opencl.h"

namespace clr {

// The OpenCL C name of a type passed by value, as the kernel declares it. Undefined for any
// other type, so that a value of a type no kernel takes does not compile; CLR_KERNEL_VALUE_TYPE
// names one.
template <typename T>
struct KernelValueType;
#define CLR_KERNEL_VALUE_TYPE(Type, opencl_name)         \
    template <>                                          \
    struct KernelValueType<Type> {                       \
        static constexpr const char* name = opencl_name; \
    };
CLR_KERNEL_VALUE_TYPE(cl_int, "int")
CLR_KERNEL_VALUE_TYPE(cl_uint, "uint")
CLR_KERNEL_VALUE_TYPE(cl_float, "float")

// Whether T is an argument group: a type that visits its parameters itself.
template <typename T, typename = void>
struct IsKernelArgGroup : std::false_type {};
struct KernelArgVisitorProbe {
    template <typename Value>
    void operator()(const char*, const Value&) {}
};
template <typename T>
struct IsKernelArgGroup<T, std::void_t<decltype(std::declval<const T&>().for_each_arg(
                               std::declval<KernelArgVisitorProbe&>()))>> : std::true_type {};

// One kernel parameter as the host declares it.
struct KernelParam {
    std::string name;
    bool global_buffer = false;  // a cl::Buffer, for a __global pointer; otherwise a value
    std::string type_name;       // the value's OpenCL C type; empty for a buffer
};

// Sets arguments 0, 1, 2, ... of one kernel, one per value visited.
class KernelArgSetter {
public:
    explicit KernelArgSetter(cl::Kernel& kernel) : kernel_(kernel) {}

    template <typename T>
    void operator()(const char*, const T& value) {
        if constexpr (IsKernelArgGroup<T>::value)
            value.for_each_arg(*this);
        else
            kernel_.setArg(next_++, value);
    }

private:
    cl::Kernel& kernel_;
    cl_uint next_ = 0;
};

// Lists the parameters visited, argument groups expanded.
class KernelParamLister {
public:
    template <typename T>
    void operator()(const char* name, const T& value) {
        if constexpr (IsKernelArgGroup<T>::value)
            value.for_each_arg(*this);
        else if constexpr (std::is_same_v<T, cl::Buffer>)
            params_.push_back({name, true, ""});
        else
            params_.push_back({name, false, KernelValueType<T>::name});
    }
    std::vector<KernelParam> take() { return std::move(params_); }

private:
    std::vector<KernelParam> params_;
};

template <typename... Params>
class KernelSignature {
public:
    // One name per parameter, as the kernel spells it; an argument group's entry only labels
    // the group (its parameters carry their own names).
    using Names = std::array<const char*, sizeof...(Params)>;

    KernelSignature(const char* kernel_name, Names names) : kernel_name_(kernel_name), names_(names) {}

    const char* kernel_name() const { return kernel_name_; }

    // Every parameter of the kernel in declaration order, argument groups expanded.
    std::vector<KernelParam> params() const {
        KernelParamLister list;
        std::size_t i = 0;
        (list(names_[i++], Params{}), ...);
        return list.take();
    }

    // Sets every argument of `kernel` from `values`, which must be exactly Params.
    template <typename... Values>
    void bind(cl::Kernel& kernel, const Values&... values) const {
        static_assert(sizeof...(Values) == sizeof...(Params), "one value per kernel parameter");
        static_assert((std::is_same_v<Values, Params> && ...), "each value of its parameter's exact type");
        KernelArgSetter set(kernel);
        (set("", values), ...);
    }

private:
    const char* kernel_name_;
    Names names_;
};

// A kernel of one program, bound only through its signature.
template <typename Signature>
class TypedKernel {
public:
    TypedKernel() = default;  // no kernel yet (one the renderer does not use)
    TypedKernel(const cl::Program& program, const Signature& signature)
        : signature_(&signature), kernel_(program, signature.kernel_name()) {}

    // Sets every argument; returns the kernel, ready to enqueue.
    template <typename... Values>
    cl::Kernel& bind(const Values&... values) {
        signature_->bind(kernel_, values...);
        return kernel_;
    }

private:
    const Signature* signature_ = nullptr;
    cl::Kernel kernel_;
};

}  // namespace clr
