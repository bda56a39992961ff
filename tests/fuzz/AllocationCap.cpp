// Linked into the fuzz target only. While an input is read, three limits make OSG's reader give up
// with std::bad_alloc, which the harness counts as a rejected input (as a machine with less memory
// would). OSG's reader trusts counts and lengths from the file:
// - size: a string's length is allocated and zero-filled before it is read, so a corrupt .osgb asks
//   for up to 2 GB per string. No legitimate read of a <= 4 kB input allocates 4 MB at once (the
//   water grid, the largest array, is only built when drawn or bounded, never while reading);
// - count: a loop count read from a corrupt file (the custom domains of the .osgb header,
//   descriptions, children) runs that many times over the exhausted stream, allocating an exception
//   record each time, for seconds or minutes. A 4 kB file, WaterNode round trips included, needs
//   under 10^4 allocations (1,700 to 7,700 for the seeds): past 10^5 the input is rejected;
// - bytes: 64 MB in all.
// Real files fail the same way, only slowly or with more memory; here the fuzzer spends its time on
// our classes instead. Every form of new and delete is replaced so that all of them pair malloc with
// free (AddressSanitizer still checks those).
#include <cstdlib>
#include <new>

namespace {
constexpr std::size_t kCap = std::size_t(4) << 20;
constexpr long kBudget = 100000;
constexpr std::size_t kBytes = std::size_t(64) << 20;
long allocations = 0; // libFuzzer runs one input at a time, on one thread
std::size_t bytes = 0;
bool counting = false; // libFuzzer's own allocations between inputs are not limited

void* allocate(std::size_t n)
{
    if (counting && (n > kCap || ++allocations > kBudget || (bytes += n) > kBytes)) throw std::bad_alloc();
    if (void* p = std::malloc(n ? n : 1)) return p;
    throw std::bad_alloc();
}
}

void* operator new(std::size_t n) { return allocate(n); }
void* operator new[](std::size_t n) { return allocate(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept
{
    return counting && n > kCap ? nullptr : std::malloc(n ? n : 1);
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept
{
    return counting && n > kCap ? nullptr : std::malloc(n ? n : 1);
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }

void osgwaterFuzzCountAllocations(bool on)
{
    allocations = 0;
    bytes = 0;
    counting = on;
}
