"""Reading the runtime conformance kit (docs/conformance.md) from Python: the
manifest, each case's sidecar and data, and the one tolerance table. Shared by
the kit's own checks and the Python loaders (core, Maya glue); no numpy here."""
import json
import os


class Kit:
    """manifest: the parsed manifest.json; dir: the kit folder."""

    def __init__(self, directory):
        self.dir = directory
        with open(os.path.join(directory, "manifest.json"), encoding="utf-8") as f:
            self.manifest = json.load(f)

    def tolerance(self, quantity, precision="float64"):
        """Absolute tolerance of `quantity` ("features" or "weights")."""
        return float(self.manifest["tolerances"][quantity][precision])

    def cases(self):
        """Yields (entry, sidecar dict, data dict) per case, in manifest order."""
        for entry in self.manifest["cases"]:
            with open(os.path.join(self.dir, entry["sidecar"]), encoding="utf-8") as f:
                sidecar = json.load(f)
            with open(os.path.join(self.dir, entry["data"]), encoding="utf-8") as f:
                data = json.load(f)
            yield entry, sidecar, data

    def bad(self):
        """Yields (entry, text) per malformed sidecar: entry["error"] is the field named."""
        for entry in self.manifest["bad"]:
            with open(os.path.join(self.dir, entry["sidecar"]), encoding="utf-8") as f:
                yield entry, f.read()


def quaternion_matrix(q):
    """3x3 rotation (nested lists) of a unit quaternion (x, y, z, w), Hamilton."""
    x, y, z, w = q
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]


def max_error(a, b):
    """Largest |a_i - b_i|; inf when the lengths differ."""
    if len(a) != len(b):
        return float("inf")
    return max((abs(x - y) for x, y in zip(a, b)), default=0.0)
