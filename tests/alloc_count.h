// Counts the C++ heap allocations of the process (the test binary replaces the global operator new),
// so a test can see that a stretch of code allocates nothing. The driver's own allocations (C's malloc)
// are not counted.
#pragma once

namespace shadowlab::test {

long allocations();

}  // namespace shadowlab::test
