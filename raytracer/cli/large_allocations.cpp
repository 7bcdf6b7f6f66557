// The program's replacement of the global operator new (part of the sweeptrace executable only,
// not of the library the tests link): blocks of 2 MiB and more are 2 MiB-aligned and advised to
// the kernel as transparent huge pages (madvise MADV_HUGEPAGE).
//
// Why: Debian's kernels ship THP in "madvise" mode, so without the advice every big per-pixel
// buffer (the film's sums, the AOVs' exact sums of 528 B per pixel, the denoiser's planes) is
// faulted in 4 KiB at a time, and in a virtual machine each fault is expensive: `render --aovs`
// of 640x360 at 1 spp measured 0.68-0.85 s user + 0.41-0.56 s system with 4 KiB pages against
// 0.39-0.42 s + 0.05-0.07 s with huge pages (glibc's tunable glibc.malloc.hugetlb=1, which does
// the same for malloc but only when set in the environment before the program starts).
// The cost: a block's size is rounded up to 2 MiB, under 2 MiB per block of at least 2 MiB.
// Memory is still released by free(), as the default operator delete does: aligned_alloc's
// blocks are free()'d like malloc's.
// Under AddressSanitizer nothing is replaced: its own operator new and delete check that every
// block is released by the form that allocated it, a check a malloc-based new would fail.
#include <sys/mman.h>

#include <cstddef>
#include <cstdlib>
#include <new>

#if defined(__SANITIZE_ADDRESS__)  // GCC's marker
#define SWEEPTRACE_ADDRESS_SANITIZER 1
#elif defined(__has_feature)  // Clang's
#if __has_feature(address_sanitizer)
#define SWEEPTRACE_ADDRESS_SANITIZER 1
#endif
#endif

#if !defined(SWEEPTRACE_ADDRESS_SANITIZER)

namespace {

// The x86-64 huge page (a page-middle-directory entry maps 2 MiB). On a machine whose huge
// pages differ the advice only covers part of a block, which is harmless.
constexpr std::size_t kHugePage = std::size_t{2} << 20;

void* allocate(std::size_t n) {
    for (;;) {
        void* p = nullptr;
        if (n >= kHugePage) {
            const std::size_t rounded = (n + kHugePage - 1) & ~(kHugePage - 1);
            if (rounded >= n) p = std::aligned_alloc(kHugePage, rounded);
            if (p != nullptr) madvise(p, rounded, MADV_HUGEPAGE);  // advice only: failure changes nothing
        } else {
            p = std::malloc(n == 0 ? 1 : n);
        }
        if (p != nullptr) return p;
        std::new_handler handler = std::get_new_handler();
        if (handler == nullptr) throw std::bad_alloc();
        handler();
    }
}

}  // namespace

// The standard's default array and nothrow forms call this one.
void* operator new(std::size_t n) { return allocate(n); }

#endif  // !SWEEPTRACE_ADDRESS_SANITIZER
