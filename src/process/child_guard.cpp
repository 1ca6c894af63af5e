#include "process/child_guard.h"

#include <signal.h>
#include <sys/resource.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif

#include "plan/limits.h"

#if defined(__SANITIZE_ADDRESS__)
#define GLIMMER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define GLIMMER_ASAN 1
#endif
#endif

namespace glimmer {

std::uint64_t sandboxAddressSpaceBytes(std::uint64_t maxMemoryMiB) {
#ifdef GLIMMER_ASAN
    (void)maxMemoryMiB;
    return 0;
#else
    const std::uint64_t budget = maxMemoryMiB > 0 ? maxMemoryMiB : kDefaultMaxMemoryMiB;
    return (budget + kDriverHeadroomMiB) << 20;
#endif
}

void guardChild(pid_t parent, std::uint64_t addressSpaceBytes) {
#ifdef __linux__
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
#endif
    // The parent may have died between fork and prctl: then no signal comes.
    if (::getppid() != parent) ::_exit(1);
    if (addressSpaceBytes > 0) {
        rlimit r{addressSpaceBytes, addressSpaceBytes};
        ::setrlimit(RLIMIT_AS, &r);
    }
}

}  // namespace glimmer
