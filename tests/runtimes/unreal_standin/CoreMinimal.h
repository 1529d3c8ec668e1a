// Stand-in for Unreal Engine's CoreMinimal.h: only what the SMPL Correctives
// plugin's glue uses, with the same names and call shapes, so its .cpp files
// compile and run in CI. Not Unreal: strings are UTF-8 std::string, the
// reflection macros expand to nothing.
#pragma once

#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#define UENUM(...)
#define USTRUCT(...)
#define UCLASS(...)
#define UPROPERTY(...)
#define GENERATED_BODY()
#define SMPLCORRECTIVES_API
#define SMPLCORRECTIVESEDITOR_API
#define TEXT(x) x
#define TCHAR_TO_UTF8(x) (x)
#define UTF8_TO_TCHAR(x) (x)

using TCHAR = char;
using uint8 = std::uint8_t;
using int32 = std::int32_t;

class FString {
 public:
  FString() = default;
  FString(const char* s) : s_(s) {}
  explicit FString(std::string s) : s_(std::move(s)) {}
  bool IsEmpty() const { return s_.empty(); }
  const TCHAR* operator*() const { return s_.c_str(); }
  FString operator+(const FString& o) const { return FString(s_ + o.s_); }
  FString& operator+=(const FString& o) {
    s_ += o.s_;
    return *this;
  }
  bool operator==(const FString& o) const { return s_ == o.s_; }
  const std::string& Std() const { return s_; }
  static FString Printf(const TCHAR* format, ...) {
    char buffer[1024];
    va_list args;
    va_start(args, format);
    std::vsnprintf(buffer, sizeof buffer, format, args);
    va_end(args);
    return FString(buffer);
  }

 private:
  std::string s_;
};

class FName {
 public:
  FName() = default;
  explicit FName(const TCHAR* s) : s_(s) {}
  FString ToString() const { return FString(s_); }
  bool operator<(const FName& o) const { return s_ < o.s_; }

 private:
  std::string s_;
};

template <class T>
class TArray {
 public:
  void Reset() { v_.clear(); }
  int32 Add(const T& x) {
    v_.push_back(x);
    return int32(v_.size()) - 1;
  }
  int32 Num() const { return int32(v_.size()); }
  T& operator[](int32 i) { return v_.at(size_t(i)); }
  const T& operator[](int32 i) const { return v_.at(size_t(i)); }

 private:
  std::vector<T> v_;
};

struct FVector {
  double X = 0, Y = 0, Z = 0;
  FVector() = default;
  FVector(double x, double y, double z) : X(x), Y(y), Z(z) {}
};

/// Hamilton quaternion (X, Y, Z, W), as Unreal's FQuat; a * b applies b first.
struct FQuat {
  double X = 0, Y = 0, Z = 0, W = 1;
  FQuat() = default;
  FQuat(double x, double y, double z, double w) : X(x), Y(y), Z(z), W(w) {}
  FQuat operator*(const FQuat& b) const {
    return FQuat(W * b.X + X * b.W + Y * b.Z - Z * b.Y, W * b.Y + Y * b.W + Z * b.X - X * b.Z,
                 W * b.Z + Z * b.W + X * b.Y - Y * b.X, W * b.W - X * b.X - Y * b.Y - Z * b.Z);
  }
  FQuat Inverse() const { return FQuat(-X, -Y, -Z, W); }
};

struct FTransform {
  FQuat Rotation;
  FTransform() = default;
  explicit FTransform(const FQuat& q) : Rotation(q) {}
  FQuat GetRotation() const { return Rotation; }
};

struct FFilePath {
  FString FilePath;
};

// Log lines the glue writes (UE_LOG), kept for the test to read.
inline std::vector<std::string>& StandInLog() {
  static std::vector<std::string> lines;
  return lines;
}
#define DEFINE_LOG_CATEGORY_STATIC(...)
#define UE_LOG(Category, Verbosity, Format, ...) \
  StandInLog().push_back(*FString::Printf(Format, __VA_ARGS__))
