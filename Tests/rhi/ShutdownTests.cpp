// Clean shutdown: the last external reference to the device destroys it
// (vkDestroyDevice, so the validation layer's undestroyed-object checks run)
// even when frames still hold timestamp queries that were never read, and
// destroying it raises no validation message.
#include <gtest/gtest.h>

#include <mutex>
#include <string>
#include <vector>

#include "d3dl/D3DLike.h"

using namespace d3dl;

namespace {
struct Log {
  std::mutex mutex;
  std::vector<std::string> validation;
  static void Thunk(LogLevel level, const char* message, void* user) {
    auto* self = static_cast<Log*>(user);
    std::lock_guard<std::mutex> lock(self->mutex);
    if (level == LogLevel::Validation || level == LogLevel::Error) self->validation.push_back(message ? message : "");
  }
};

// A device description whose validation messages go to *log.
DEVICE_CREATE_DESC LoggingDesc(Log* log) {
  DEVICE_CREATE_DESC desc;
  desc.Validation = ValidationMode::FromEnvironment;
  desc.Log = &Log::Thunk;
  desc.LogUser = log;
  return desc;
}
}  // namespace

TEST(RhiShutdown, DeviceIsDestroyedWithUnreadQueriesInFlight) {
  Log log;
  const DEVICE_CREATE_DESC desc = LoggingDesc(&log);
  const UINT before = LiveDeviceCount();
  {
    ComPtr<Device> device;
    ComPtr<DeviceContext> context;
    ASSERT_EQ(CreateDevice(&desc, device.GetAddressOf(), context.GetAddressOf()), S_OK);
    EXPECT_EQ(LiveDeviceCount(), before + 1);
    QUERY_DESC qd;
    qd.Query = QUERY_TIMESTAMP_DISJOINT;
    ComPtr<Query> disjoint, stamp;
    ASSERT_EQ(device->CreateQuery(&qd, disjoint.GetAddressOf()), S_OK);
    qd.Query = QUERY_TIMESTAMP;
    ASSERT_EQ(device->CreateQuery(&qd, stamp.GetAddressOf()), S_OK);
    for (int frame = 0; frame < 3; ++frame) {  // ended, submitted, never read back
      context->Begin(disjoint.Get());
      context->End(stamp.Get());
      context->End(disjoint.Get());
      context->Flush();
    }
    // The application's references go in the usual order: queries first.
  }
  EXPECT_EQ(LiveDeviceCount(), before) << "the device outlived its last reference";
  EXPECT_TRUE(log.validation.empty()) << log.validation.size() << " messages, first: " << log.validation[0];
}

TEST(RhiShutdown, DeviceReleasedBeforeItsChildrenIsDestroyedWithTheLastChild) {
  Log log;
  const DEVICE_CREATE_DESC desc = LoggingDesc(&log);
  const UINT before = LiveDeviceCount();
  ComPtr<Device> device;
  ComPtr<DeviceContext> context;
  ASSERT_EQ(CreateDevice(&desc, device.GetAddressOf(), context.GetAddressOf()), S_OK);
  QUERY_DESC qd;
  qd.Query = QUERY_TIMESTAMP;
  ComPtr<Query> stamp;
  ASSERT_EQ(device->CreateQuery(&qd, stamp.GetAddressOf()), S_OK);
  context->End(stamp.Get());
  context->Flush();
  context.Reset();
  device.Reset();
  EXPECT_EQ(LiveDeviceCount(), before + 1) << "a child (the query) still holds the device";
  stamp.Reset();
  EXPECT_EQ(LiveDeviceCount(), before);
  EXPECT_TRUE(log.validation.empty()) << log.validation.size() << " messages, first: " << log.validation[0];
}
