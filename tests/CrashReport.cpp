// A GL test that dies of a signal (an abort from the allocator's checks, a segfault) prints the
// test it was in and the stack before it goes: CI keeps only the log, and a crash that happens once
// in many runs has to be found from that. Off under AddressSanitizer, which reports with its own.
#include <gtest/gtest.h>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <execinfo.h>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__)
#define OSGWATER_TEST_CRASH_REPORT 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define OSGWATER_TEST_CRASH_REPORT 0
#endif
#endif
#ifndef OSGWATER_TEST_CRASH_REPORT
#define OSGWATER_TEST_CRASH_REPORT 1
#endif

namespace {

#if OSGWATER_TEST_CRASH_REPORT
void write(const char* s) { (void)!::write(STDERR_FILENO, s, std::strlen(s)); }

void report(int sig)
{
    write("\n*** fatal signal ");
    write(sig == SIGABRT ? "SIGABRT" : sig == SIGSEGV ? "SIGSEGV" : sig == SIGBUS ? "SIGBUS" : "SIGFPE");
    // the test's name: not async-signal-safe, but the process is going anyway
    if (const testing::TestInfo* t = testing::UnitTest::GetInstance()->current_test_info()) {
        write(" in ");
        write(t->test_suite_name());
        write(".");
        write(t->name());
    }
    write("; the stack (addr2line -e <file> <offset> names a line):\n");
    void* frames[64];
    backtrace_symbols_fd(frames, backtrace(frames, 64), STDERR_FILENO);
    std::signal(sig, SIG_DFL); // the default action ends it, with the status CTest expects
    std::raise(sig);
}

const bool installed = [] {
    void* warm[1];
    backtrace(warm, 1); // loads libgcc's unwinder now, not inside the handler
    for (int sig : { SIGABRT, SIGSEGV, SIGBUS, SIGFPE }) std::signal(sig, report);
    return true;
}();
#endif

}
