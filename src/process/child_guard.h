// What every child process that runs a student's script gets, in one place
// (the --timeout watchdog and batch's workers fork them):
//   - it dies with its parent: a parent killed by SIGKILL or SIGTERM never
//     leaves a renderer spinning on with parent pid 1 (Linux's
//     PR_SET_PDEATHSIG; issue 30);
//   - under --sandbox, its address space is bounded (RLIMIT_AS), so a shader
//     that makes the driver's compiler eat memory ends as an error, never as
//     the machine swapping: --max-memory plus room for the driver itself.
#pragma once
#include <cstdint>
#include <sys/types.h>

namespace glimmer {

// The address space a sandboxed renderer may use: the --max-memory budget
// (0: the default) plus kDriverHeadroomMiB for the driver's own code,
// threads and compiler. 0 under AddressSanitizer, whose shadow memory
// reserves terabytes of address space it never uses.
constexpr std::uint64_t kDriverHeadroomMiB = 4096;
std::uint64_t sandboxAddressSpaceBytes(std::uint64_t maxMemoryMiB);

// Called first thing in a forked child: ties it to `parent` (the pid before
// the fork), and bounds its address space to `addressSpaceBytes` (0: no
// bound). Exits at once if the parent is already gone.
void guardChild(pid_t parent, std::uint64_t addressSpaceBytes);

}  // namespace glimmer
