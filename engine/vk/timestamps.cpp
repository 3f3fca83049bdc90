#include "vk/timestamps.h"

#include "vk/check.h"

namespace candela::vk {

bool timestampsMeasurePasses(VkDriverId driver) { return driver != VK_DRIVER_ID_MESA_LLVMPIPE; }

const char* timestampBehaviour(VkDriverId driver) {
    if (driver == VK_DRIVER_ID_MESA_LLVMPIPE)
        return "per-pass times unreliable: llvmpipe rasterizes a render pass's draws when the render pass ends, after the "
               "pass's closing timestamp (`candela bench` measures each pass submitted alone)";
    if (driver == VK_DRIVER_ID_GOOGLE_SWIFTSHADER)
        return "per-pass times measured: SwiftShader finishes the work recorded before a timestamp before it writes it";
    return "per-pass times measured: each timestamp is written when the work recorded before it has finished";
}

TimestampPool::TimestampPool(Context& context, uint32_t capacity)
    : mContext(&context), mCapacity(capacity), mMeasuresPasses(timestampsMeasurePasses(context.caps().driver)) {
    const DeviceReport& report = context.report();
    if (report.timestampValidBits == 0 || capacity == 0) return;
    mPeriodNs = report.timestampPeriodNs;
    mMask = report.timestampValidBits >= 64 ? ~0ull : (1ull << report.timestampValidBits) - 1;
    const VkQueryPoolCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO, .queryType = VK_QUERY_TYPE_TIMESTAMP, .queryCount = capacity};
    VkQueryPool pool = VK_NULL_HANDLE;
    VK_CHECK(vkCreateQueryPool(context.device(), &info, nullptr, &pool));
    mPool = QueryPool(context, pool);
}

void TimestampPool::reset(VkCommandBuffer cmd) {
    mUsed = 0;
    mResults.clear();
    if (mPool) vkCmdResetQueryPool(cmd, mPool.get(), 0, mCapacity);
}

std::optional<uint32_t> TimestampPool::write(VkCommandBuffer cmd, VkPipelineStageFlags2 stage) {
    if (!mPool || mUsed == mCapacity) return std::nullopt;
    vkCmdWriteTimestamp2(cmd, stage, mPool.get(), mUsed);
    return mUsed++;
}

void TimestampPool::fetch() {
    mResults.assign(static_cast<size_t>(mUsed) * 2, 0);
    if (!mPool || mUsed == 0) return;
    VK_CHECK(vkGetQueryPoolResults(mContext->device(), mPool.get(), 0, mUsed, mResults.size() * sizeof(uint64_t),
                                   mResults.data(), 2 * sizeof(uint64_t),
                                   VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WITH_AVAILABILITY_BIT));
}

double TimestampPool::elapsedMs(uint32_t begin, uint32_t end) {
    if (2 * static_cast<size_t>(end) + 1 >= mResults.size()) return -1.0;
    if (!mResults[2 * begin + 1] || !mResults[2 * end + 1]) return -1.0;
    const uint64_t ticks = (mResults[2 * end] - mResults[2 * begin]) & mMask;
    return static_cast<double>(ticks) * mPeriodNs * 1e-6;
}

}  // namespace candela::vk
