"""A small stand-in for the parts of Maya's Python API that smpl_maya calls,
for CI (no Maya here). Not Maya: it models only what the tests need, with
Maya's documented conventions where they matter (row-vector 4x4 matrices,
blendShape aliases, skinCluster matrix/bindPreMatrix plugs)."""
