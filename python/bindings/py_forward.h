// Model.forward: vertices and joints of a body model for T poses, on numpy
// arrays, with the GIL released while it computes.
//
//   v_shaped = T + S beta (+ E psi), J = J_regressor v_shaped, then per frame
//   the posed vertices of docs/file-contract.md "The math" (SMPL, Loper et al.
//   2015, eqs. 1-9) plus the translation.
//
// One shape for every frame (betas (B,), expression (E,) or equal rows): the
// batched pass (core/math/forward_batch.h: float32 correctives, < 1e-6 m from
// the double reference) over all frames on every core; betas or expression
// that change per frame: the double reference pass (core/math/forward.h) per
// frame.
#pragma once

#include <pybind11/pybind11.h>

#include "python/bindings/py_model.h"

namespace smpl::py {

// betas (B,) or (T,B) with B <= the model's; poses (T,K,3) or (T,3K)
// axis-angle in radians, or (T,K,3,3) rotation matrices, in the model's joint
// order, local to each parent; trans (T,3) or (3,) metres or None;
// expression (E,) or (T,E) or None; dtype float32 or float64. Returns
// (vertices (T,V,3), joints (T,K,3)) in metres, model axes. Errors
// (usage, exit 1): shapes, counts larger than the model's, NaN.
pybind11::tuple forwardModel(const PyModel& model, const pybind11::object& betas,
                             const pybind11::object& poses, const pybind11::object& trans,
                             const pybind11::object& expression, const pybind11::object& dtype);

}  // namespace smpl::py
