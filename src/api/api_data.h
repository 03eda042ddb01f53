#pragma once
// What the public handles hold (private: hosts see only the forward declarations), and how library
// errors become crowdgpu::Error.
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include "crowd/crowd.h"
#include "crowdgpu/crowd.hpp"
#include "crowdgpu/error.hpp"
#include "crowdgpu/model.hpp"
#include "gpu/error.h"
#include "model/prop_mesh.h"
#include "model/skinned_model.h"

namespace crowdgpu::detail {

struct ModelData {
    model::SkinnedModel model;
    std::vector<std::string> notes;
};

struct PropData {
    model::PropMesh mesh;
};

struct CrowdData {
    std::vector<Model> models;  // keep the internal crowd's models alive
    std::optional<crowd::Crowd> owned;
    crowd::Crowd* borrowed = nullptr;  // an internal crowd somebody else keeps (the library's tests)
    crowd::Crowd& crowd() { return borrowed ? *borrowed : *owned; }
    const crowd::Crowd& crowd() const { return borrowed ? *borrowed : *owned; }
};

// Runs `f`, turning the library's internal failures into crowdgpu::Error with the same message.
template <class F>
auto translated(F&& f) -> decltype(f()) {
    try {
        return f();
    } catch (const Error&) {
        throw;
    } catch (const gpu::Error& error) {
        throw Error(static_cast<ErrorCode>(error.kind()), error.what());
    } catch (const std::bad_alloc&) {
        throw Error(ErrorCode::OutOfHostMemory, "out of host memory");
    }
}

// The internal models of a list of public ones, in order.
std::vector<const model::SkinnedModel*> internalModels(const std::vector<Model>& models);

}  // namespace crowdgpu::detail
