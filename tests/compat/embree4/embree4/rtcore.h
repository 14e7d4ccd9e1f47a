// A compile-only stand-in for Embree 4's <embree4/rtcore.h>: the declarations oracle/oracle.cpp uses,
// as Embree 4's manual pages give them (rtcOccluded1(3), rtcInitOccludedArguments(3), RTCRay(3),
// rtcSetDeviceErrorFunction(3), rtcSetSceneFlags(3), rtcSetNewGeometryBuffer(3), RTCError in
// rtcGetDeviceError(3); the filter functions at the end). This machine has only Embree 3; tests/CMakeLists.txt compiles the oracle's
// Embree 4 branch against this file so a call that Embree 4 no longer has (rtcInitIntersectContext, the
// context argument of rtcOccluded1) fails the build here. It is never linked or run.
#pragma once

#include <stddef.h>

#define RTC_VERSION_MAJOR 4

typedef struct RTCDeviceTy* RTCDevice;
typedef struct RTCSceneTy* RTCScene;
typedef struct RTCGeometryTy* RTCGeometry;

enum RTCError {
  RTC_ERROR_NONE = 0,
  RTC_ERROR_UNKNOWN = 1,
  RTC_ERROR_INVALID_ARGUMENT = 2,
  RTC_ERROR_INVALID_OPERATION = 3,
  RTC_ERROR_OUT_OF_MEMORY = 4,
  RTC_ERROR_UNSUPPORTED_CPU = 5,
  RTC_ERROR_CANCELLED = 6,
  RTC_ERROR_LEVEL_ZERO_RAYTRACING_SUPPORT_MISSING = 7,
};
typedef void (*RTCErrorFunction)(void* userPtr, enum RTCError code, const char* str);

RTCDevice rtcNewDevice(const char* config);
void rtcReleaseDevice(RTCDevice device);
enum RTCError rtcGetDeviceError(RTCDevice device);
void rtcSetDeviceErrorFunction(RTCDevice device, RTCErrorFunction error, void* userPtr);

enum RTCSceneFlags {
  RTC_SCENE_FLAG_NONE = 0,
  RTC_SCENE_FLAG_DYNAMIC = (1 << 0),
  RTC_SCENE_FLAG_COMPACT = (1 << 1),
  RTC_SCENE_FLAG_ROBUST = (1 << 2),
  RTC_SCENE_FLAG_FILTER_FUNCTION_IN_ARGUMENTS = (1 << 3),
};
RTCScene rtcNewScene(RTCDevice device);
void rtcReleaseScene(RTCScene scene);
void rtcSetSceneFlags(RTCScene scene, enum RTCSceneFlags flags);
void rtcCommitScene(RTCScene scene);

enum RTCGeometryType { RTC_GEOMETRY_TYPE_TRIANGLE = 0 };
enum RTCBufferType { RTC_BUFFER_TYPE_INDEX = 0, RTC_BUFFER_TYPE_VERTEX = 1 };
enum RTCFormat { RTC_FORMAT_UINT3 = 0x5003, RTC_FORMAT_FLOAT3 = 0x9003 };
RTCGeometry rtcNewGeometry(RTCDevice device, enum RTCGeometryType type);
void* rtcSetNewGeometryBuffer(RTCGeometry geometry, enum RTCBufferType type, unsigned int slot, enum RTCFormat format,
                              size_t byteStride, size_t itemCount);
void rtcCommitGeometry(RTCGeometry geometry);
unsigned int rtcAttachGeometry(RTCScene scene, RTCGeometry geometry);
void rtcReleaseGeometry(RTCGeometry geometry);

struct RTCRay {
  float org_x, org_y, org_z;
  float tnear;
  float dir_x, dir_y, dir_z;
  float time;
  float tfar;
  unsigned int mask;
  unsigned int id;
  unsigned int flags;
};
struct RTCOccludedArguments;  // optional; its defaults are what the oracle wants
void rtcOccluded1(RTCScene scene, struct RTCRay* ray, struct RTCOccludedArguments* args = NULL);

// Filter functions (RTCFilterFunctionNArguments(3), rtcSetGeometryOccludedFilterFunction(3),
// rtcSetGeometryIntersectFilterFunction(3), rtcSetGeometryUserData(3), RTCHitN(3)): the oracle's
// alpha-tested casters.
struct RTCRayQueryContext;
struct RTCRayN;
struct RTCHitN;
struct RTCFilterFunctionNArguments {
  int* valid;
  void* geometryUserPtr;
  struct RTCRayQueryContext* context;
  struct RTCRayN* ray;
  struct RTCHitN* hit;
  unsigned int N;
};
typedef void (*RTCFilterFunctionN)(const struct RTCFilterFunctionNArguments* args);
void rtcSetGeometryOccludedFilterFunction(RTCGeometry geometry, RTCFilterFunctionN filter);
void rtcSetGeometryIntersectFilterFunction(RTCGeometry geometry, RTCFilterFunctionN filter);
void rtcSetGeometryUserData(RTCGeometry geometry, void* ptr);
inline float& RTCHitN_u(RTCHitN* hit, unsigned int N, unsigned int i) { return ((float*)hit)[3 * N + i]; }
inline float& RTCHitN_v(RTCHitN* hit, unsigned int N, unsigned int i) { return ((float*)hit)[4 * N + i]; }
inline unsigned& RTCHitN_primID(RTCHitN* hit, unsigned int N, unsigned int i) { return ((unsigned*)hit)[5 * N + i]; }
