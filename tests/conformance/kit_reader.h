// The conformance kit (docs/conformance.md) read in C++ for the C++ loaders
// (conformance_test.cpp): the manifest, each case's sidecar text and data.
// Errors (a missing kit, a malformed file) throw std::runtime_error naming
// the file, so a broken kit fails the loader instead of passing it.
#pragma once

#include <array>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace kit {

/// One pose of a case: K quaternions (x, y, z, w) world and local in the
/// importer's frame, the model-space axis-angle (K x 3), P features and the
/// weights (correctives in sidecar order, then basis rows).
struct Pose {
  std::vector<std::array<double, 4>> world, local;
  std::vector<double> axis_angle, features, weights;
};

/// One case: its name, frame, encoding, the sidecar's bytes, C (row-major,
/// model -> engine axes), the rest rotations and the poses.
struct Case {
  std::string name, frame, encoding, sidecar;
  std::array<double, 9> axes{};
  std::vector<std::array<double, 4>> rest_world, rest_local;
  std::vector<Pose> poses;
};

/// A malformed sidecar and the field its error must name ("json": any error).
struct Bad {
  std::string name, error, text;
};

inline std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot read (generate the kit: docs/conformance.md)");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline nlohmann::json readJson(const std::string& path) {
  try {
    return nlohmann::json::parse(readText(path));
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
}

inline std::vector<std::array<double, 4>> quaternions(const nlohmann::json& a) {
  std::vector<std::array<double, 4>> out;
  for (const auto& q : a) out.push_back({q.at(0), q.at(1), q.at(2), q.at(3)});
  return out;
}

/// The kit folder: $SMPL_CONFORMANCE_KIT (set by tests/conformance/tests.cmake).
inline std::string kitDir() {
  const char* d = std::getenv("SMPL_CONFORMANCE_KIT");
  if (!d || !*d) throw std::runtime_error("SMPL_CONFORMANCE_KIT is not set (the kit's folder)");
  return d;
}

struct Kit {
  std::string dir;
  nlohmann::json manifest;
  explicit Kit(const std::string& d) : dir(d), manifest(readJson(d + "/manifest.json")) {}

  /// Absolute tolerance of "features" or "weights" for "float64" or "float32".
  double tolerance(const char* quantity, const char* precision) const {
    return manifest.at("tolerances").at(quantity).at(precision).get<double>();
  }

  std::vector<Case> cases() const {
    std::vector<Case> out;
    for (const auto& e : manifest.at("cases")) {
      Case c;
      c.name = e.at("name");
      c.frame = e.at("frame");
      c.encoding = e.at("encoding");
      c.sidecar = readText(dir + "/" + e.at("sidecar").get<std::string>());
      const std::string data_path = dir + "/" + e.at("data").get<std::string>();
      nlohmann::json d = readJson(data_path);
      try {
        for (int i = 0; i < 9; ++i) c.axes[size_t(i)] = d.at("axes").at(size_t(i));
        c.rest_world = quaternions(d.at("rest_world"));
        c.rest_local = quaternions(d.at("rest_local"));
        for (const auto& p : d.at("poses"))
          c.poses.push_back(Pose{quaternions(p.at("world")), quaternions(p.at("local")),
                                 p.at("axis_angle"), p.at("features"), p.at("weights")});
      } catch (const nlohmann::json::exception& ex) {
        throw std::runtime_error(data_path + ": " + ex.what());
      }
      out.push_back(std::move(c));
    }
    if (out.empty()) throw std::runtime_error(dir + "/manifest.json: no cases");
    return out;
  }

  std::vector<Bad> bad() const {
    std::vector<Bad> out;
    for (const auto& e : manifest.at("bad"))
      out.push_back(Bad{e.at("name"), e.at("error"),
                        readText(dir + "/" + e.at("sidecar").get<std::string>())});
    return out;
  }
};

/// Largest |a_i - b_i| (infinity when the lengths differ).
inline double maxError(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return 1.0 / 0.0;
  double e = 0;
  for (size_t i = 0; i < a.size(); ++i) e = std::max(e, std::abs(a[i] - b[i]));
  return e;
}

}  // namespace kit
