// The buffers between the spray's passes (spray_buffers.h).
#include "render/spray_buffers.h"
#include "swell/gpu/bindings.h"

namespace swell::detail {

void SprayBuffers::bind(long long slotsDrawn, long long recordBytes, int strips)
{
    if (!clumps || slots < slotsDrawn || bytesARecord != recordBytes) {
        slots = slotsDrawn;
        bytesARecord = recordBytes;
        clumps = gl::Buffer::create();
        glNamedBufferStorage(clumps.id(), GLsizeiptr(slots * recordBytes), nullptr, 0);
        list = gl::Buffer::create();
        glNamedBufferStorage(list.id(), GLsizeiptr(slots * 4), nullptr, 0);
        commands = gl::Buffer::create();
        glNamedBufferStorage(commands.id(), GLsizeiptr(kSprayCommandsBytes), nullptr, 0);
        streaks = gl::Buffer::create();
        glNamedBufferStorage(streaks.id(), GLsizeiptr(slots * strips * kSprayStreakBytes), nullptr, 0);
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SWELL_STORAGE_SPRAY_CLUMPS, clumps.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SWELL_STORAGE_SPRAY_LIST, list.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SWELL_STORAGE_SPRAY_COMMANDS, commands.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SWELL_STORAGE_SPRAY_STREAKS, streaks.id());
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, commands.id());
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, commands.id());
}

GpuWork sprayPassWork(long long slots, long long recordBytes)
{
    GpuWork work;
    work.dispatches = 3;
    work.barriers = 3;
    work.bytesWritten = slots * recordBytes + slots * 4 + kSprayCommandsBytes;
    return work;
}

} // namespace swell::detail
