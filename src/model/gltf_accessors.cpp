// Reading glTF accessors with every index, offset, stride and count checked against the bytes
// that are really there. Arithmetic is arranged so that no product of file values can overflow.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>

#include "model/gltf_internal.h"

namespace model::gltf {
namespace {

// Most elements one accessor may hold: 16 Mi is ~16x a detailed film character. An accessor with a
// buffer view is also bounded by the bytes really there; one without reads zeros (sparse accessors
// replace a few), so its count alone would ask for any allocation: 1 Mi elements is plenty for that.
constexpr std::size_t kMaxAccessorElements = std::size_t{1} << 24;
constexpr std::size_t kMaxZeroAccessorElements = std::size_t{1} << 20;

int componentCount(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return 1;
        case TINYGLTF_TYPE_VEC2: return 2;
        case TINYGLTF_TYPE_VEC3: return 3;
        case TINYGLTF_TYPE_VEC4: return 4;
        case TINYGLTF_TYPE_MAT2: return 4;
        case TINYGLTF_TYPE_MAT3: return 9;
        case TINYGLTF_TYPE_MAT4: return 16;
        default: return 0;
    }
}

std::size_t componentBytes(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
        case TINYGLTF_COMPONENT_TYPE_INT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
        case TINYGLTF_COMPONENT_TYPE_DOUBLE: return 8;
        default: return 0;
    }
}

std::string typeName(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return "SCALAR";
        case TINYGLTF_TYPE_VEC2: return "VEC2";
        case TINYGLTF_TYPE_VEC3: return "VEC3";
        case TINYGLTF_TYPE_VEC4: return "VEC4";
        case TINYGLTF_TYPE_MAT2: return "MAT2";
        case TINYGLTF_TYPE_MAT3: return "MAT3";
        case TINYGLTF_TYPE_MAT4: return "MAT4";
        default: return "type " + std::to_string(type);
    }
}

std::string componentTypeName(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: return "byte";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "unsigned byte";
        case TINYGLTF_COMPONENT_TYPE_SHORT: return "short";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "unsigned short";
        case TINYGLTF_COMPONENT_TYPE_INT: return "int";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "unsigned int";
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return "float";
        case TINYGLTF_COMPONENT_TYPE_DOUBLE: return "double";
        default: return "component type " + std::to_string(componentType);
    }
}

std::string joinNames(const std::vector<int>& values, std::string (*name)(int)) {
    std::string text;
    for (std::size_t i = 0; i < values.size(); ++i)
        text += (i == 0 ? "" : i + 1 == values.size() ? " or " : ", ") + name(values[i]);
    return text;
}

template <typename T>
double load(const std::uint8_t* p) {
    T value;
    std::memcpy(&value, p, sizeof(T));  // file data has no alignment guarantee
    return static_cast<double>(value);
}

double readComponent(const std::uint8_t* p, int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: return load<std::int8_t>(p);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return load<std::uint8_t>(p);
        case TINYGLTF_COMPONENT_TYPE_SHORT: return load<std::int16_t>(p);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return load<std::uint16_t>(p);
        case TINYGLTF_COMPONENT_TYPE_INT: return load<std::int32_t>(p);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return load<std::uint32_t>(p);
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return load<float>(p);
        case TINYGLTF_COMPONENT_TYPE_DOUBLE: return load<double>(p);
        default: return 0.0;
    }
}

// glTF's normalized integers: unsigned ones divide by their maximum, signed ones too but clamp at -1.
double normalize(double value, int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: return std::max(value / 127.0, -1.0);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return value / 255.0;
        case TINYGLTF_COMPONENT_TYPE_SHORT: return std::max(value / 32767.0, -1.0);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return value / 65535.0;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return value / 4294967295.0;
        default: return value;
    }
}

const tinygltf::Accessor& checkedAccessor(const tinygltf::Model& model, int index, const AccessorRule& rule) {
    if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size())
        fail(rule.what + ": accessor " + std::to_string(index) + " does not exist (the file has " +
             std::to_string(model.accessors.size()) + ")");
    const tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(index)];
    const bool typeOk = std::find(rule.types.begin(), rule.types.end(), a.type) != rule.types.end();
    const bool componentOk =
        std::find(rule.componentTypes.begin(), rule.componentTypes.end(), a.componentType) != rule.componentTypes.end();
    if (!typeOk || !componentOk)
        fail(rule.what + ": accessor " + std::to_string(index) + " holds " + typeName(a.type) + " of " +
             componentTypeName(a.componentType) + "; expected " + joinNames(rule.types, typeName) + " of " +
             joinNames(rule.componentTypes, componentTypeName));
    const std::size_t limit = a.bufferView >= 0 ? kMaxAccessorElements : kMaxZeroAccessorElements;
    if (a.count > limit)
        fail(rule.what + ": accessor " + std::to_string(index) + " has " + std::to_string(a.count) +
             " elements (at most " + std::to_string(limit) + " are supported" +
             (a.bufferView >= 0 ? "" : " without a buffer view") + ")");
    return a;
}

// Calls sink(element, component, raw value) for every stored component of the accessor, then for
// every component its sparse substitution replaces.
template <typename Sink>
void forEachComponent(const tinygltf::Model& model, int index, const tinygltf::Accessor& a, const AccessorRule& rule,
                      Sink sink) {
    const int components = componentCount(a.type);
    const std::size_t componentSize = componentBytes(a.componentType);
    const std::size_t elementSize = componentSize * static_cast<std::size_t>(components);
    const std::string name = rule.what + ": accessor " + std::to_string(index);

    if (a.bufferView >= 0 && a.count > 0) {
        const std::span<const std::uint8_t> view = bufferViewBytes(model, a.bufferView, name);
        const std::size_t declaredStride = model.bufferViews[static_cast<std::size_t>(a.bufferView)].byteStride;
        const std::size_t stride = declaredStride != 0 ? declaredStride : elementSize;
        if (stride < elementSize)
            fail(name + ": byte stride " + std::to_string(stride) + " is smaller than its elements (" +
                 std::to_string(elementSize) + " bytes)");
        // offset + (count - 1) * stride + elementSize <= view size, without forming the product.
        if (a.byteOffset > view.size() || view.size() - a.byteOffset < elementSize ||
            (a.count - 1) > (view.size() - a.byteOffset - elementSize) / stride)
            fail(name + " (" + std::to_string(a.count) + " elements from byte " + std::to_string(a.byteOffset) +
                 ") runs past the end of buffer view " + std::to_string(a.bufferView) + " (" +
                 std::to_string(view.size()) + " bytes)");
        for (std::size_t e = 0; e < a.count; ++e) {
            const std::uint8_t* element = view.data() + a.byteOffset + e * stride;
            for (int c = 0; c < components; ++c)
                sink(e, c, readComponent(element + static_cast<std::size_t>(c) * componentSize, a.componentType));
        }
    }

    if (!a.sparse.isSparse) return;
    const auto& sparse = a.sparse;
    if (sparse.count < 1 || static_cast<std::size_t>(sparse.count) > a.count)
        fail(name + ": sparse count " + std::to_string(sparse.count) + " is not within 1.." + std::to_string(a.count));
    const std::size_t count = static_cast<std::size_t>(sparse.count);
    const std::size_t indexSize = componentBytes(sparse.indices.componentType);
    if (sparse.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        sparse.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        sparse.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        fail(name + ": sparse indices are " + componentTypeName(sparse.indices.componentType) +
             "; expected unsigned byte, short or int");
    auto region = [&](int bufferView, int offset, std::size_t bytesPerElement, const char* part) {
        const std::span<const std::uint8_t> view = bufferViewBytes(model, bufferView, name + " sparse " + part);
        if (offset < 0 || static_cast<std::size_t>(offset) > view.size() ||
            (view.size() - static_cast<std::size_t>(offset)) / bytesPerElement < count)
            fail(name + ": sparse " + part + " run past the end of buffer view " + std::to_string(bufferView));
        return view.subspan(static_cast<std::size_t>(offset));
    };
    const std::span<const std::uint8_t> indices =
        region(sparse.indices.bufferView, sparse.indices.byteOffset, indexSize, "indices");
    const std::span<const std::uint8_t> values =
        region(sparse.values.bufferView, sparse.values.byteOffset, elementSize, "values");
    for (std::size_t s = 0; s < count; ++s) {
        const auto e =
            static_cast<std::size_t>(readComponent(indices.data() + s * indexSize, sparse.indices.componentType));
        if (e >= a.count)
            fail(name + ": sparse index " + std::to_string(e) + " is beyond its " + std::to_string(a.count) +
                 " elements");
        for (int c = 0; c < components; ++c)
            sink(e, c,
                 readComponent(values.data() + s * elementSize + static_cast<std::size_t>(c) * componentSize,
                               a.componentType));
    }
}

}  // namespace

std::span<const std::uint8_t> bufferViewBytes(const tinygltf::Model& model, int bufferView, const std::string& what) {
    if (bufferView < 0 || static_cast<std::size_t>(bufferView) >= model.bufferViews.size())
        fail(what + ": buffer view " + std::to_string(bufferView) + " does not exist (the file has " +
             std::to_string(model.bufferViews.size()) + ")");
    const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(bufferView)];
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size())
        fail(what + ": buffer view " + std::to_string(bufferView) + " names buffer " + std::to_string(view.buffer) +
             ", which does not exist (the file has " + std::to_string(model.buffers.size()) + ")");
    const std::vector<unsigned char>& data = model.buffers[static_cast<std::size_t>(view.buffer)].data;
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
        fail(what + ": buffer view " + std::to_string(bufferView) + " (" + std::to_string(view.byteLength) +
             " bytes from byte " + std::to_string(view.byteOffset) + ") runs past the end of buffer " +
             std::to_string(view.buffer) + " (" + std::to_string(data.size()) + " bytes)");
    return std::span<const std::uint8_t>(data.data() + view.byteOffset, view.byteLength);
}

float toFloat(double value, const std::string& what) {
    if (!std::isfinite(value) || std::abs(value) > static_cast<double>(FLT_MAX)) fail(what + " is not a finite number");
    return static_cast<float>(value);
}

FloatData readFloats(const tinygltf::Model& model, int index, const AccessorRule& rule) {
    const tinygltf::Accessor& a = checkedAccessor(model, index, rule);
    FloatData data;
    data.count = a.count;
    data.components = componentCount(a.type);
    data.values.assign(a.count * static_cast<std::size_t>(data.components), 0.0f);
    const bool normalized = a.normalized && a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT;
    forEachComponent(model, index, a, rule, [&](std::size_t e, int c, double raw) {
        const double value = normalized ? normalize(raw, a.componentType) : raw;
        if (!std::isfinite(value) || std::abs(value) > static_cast<double>(FLT_MAX))
            fail(rule.what + ": accessor " + std::to_string(index) + " element " + std::to_string(e) +
                 " is not a finite number");
        data.values[e * static_cast<std::size_t>(data.components) + static_cast<std::size_t>(c)] =
            static_cast<float>(value);
    });
    return data;
}

UintData readUints(const tinygltf::Model& model, int index, const AccessorRule& rule) {
    const tinygltf::Accessor& a = checkedAccessor(model, index, rule);
    UintData data;
    data.count = a.count;
    data.components = componentCount(a.type);
    data.values.assign(a.count * static_cast<std::size_t>(data.components), 0u);
    forEachComponent(model, index, a, rule, [&](std::size_t e, int c, double raw) {
        // Rules admit only unsigned integer component types here, so raw is exact and in range.
        data.values[e * static_cast<std::size_t>(data.components) + static_cast<std::size_t>(c)] =
            static_cast<std::uint32_t>(raw);
    });
    return data;
}

}  // namespace model::gltf
