// Body models that are not SMPL-family but whose files look like one (the
// same array names: v_template, posedirs, kintree_table): STAR, SUPR, SKEL.
// They are named, with the way forward, instead of ending in a shape error
// ("'posedirs' has shape (6890,3,93); expected (6890,3,207)") that does not
// say what the file is.
#pragma once

#include <string>
#include <vector>

#include "core/array.h"
#include "core/result.h"

namespace smpl {

// An error "<path>: a STAR model file (...)" when `keys` (every top-level
// key of the file, read or not) and `arrays` (the arrays the model loader
// read) are those of a model this exporter does not read; Status() for
// anything else, which the usual checks then judge.
//   STAR (ahmedosman/STAR star/pytorch/star.py): posedirs (N,3,4(K-1)+1),
//     23 quaternion features per joint plus betas[1];
//   SUPR (SUPR's supr/pytorch/supr.py): posedirs (N,3,4K), J_regressor
//     (3K, 3N+1), or an 'axis_meta' entry;
//   SKEL (MarilynKeller/SKEL skel/skel_model.py): skin_template_v,
//     skel_template_v, J_regressor_osim, osim_kintree_table.
Status refuseOtherModel(const std::vector<std::string>& keys, const ArrayDict& arrays,
                        const std::string& path);

}  // namespace smpl
