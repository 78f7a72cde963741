// YADE's per-thread accumulator of an array of values (OpenMP flavour): each thread adds into its
// own cache-line-aligned chunk; reading sums the chunks. Layout and behaviour as in Debian's build.
#pragma once
#include <cstdlib>
#include <cstring>
#include <omp.h>
#include <stdexcept>
#include <unistd.h>
#include <vector>

namespace yade {
template <typename T> class OpenMPArrayAccumulator {
	int             CLS;      // cache line size [bytes]
	size_t          nThreads; // one chunk per thread
	int             perCL;    // values per cache line
	std::vector<T*> chunks;
	size_t          sz;  // values in use
	size_t          nCL; // cache lines allocated per chunk
	size_t          linesFor(size_t n) const { return n / perCL + (n % perCL == 0 ? 0 : 1); }

public:
	OpenMPArrayAccumulator() = delete; // constructed by libyade.so only
	size_t size() const { return sz; }
	void   resize(size_t n)
	{
		if (n == sz) return;
		const size_t nCLnew = linesFor(n);
		if (nCLnew > nCL) {
			for (size_t th = 0; th < nThreads; th++) {
				T* old = chunks[th];
				if (posix_memalign(reinterpret_cast<void**>(&chunks[th]), CLS, nCLnew * CLS) != 0)
					throw std::runtime_error("OpenMPArrayAccumulator: posix_memalign failed");
				if (old) {
					std::memcpy(chunks[th], old, nCL * CLS);
					std::free(old);
				}
			}
			nCL = nCLnew;
		}
		for (size_t s = sz; s < n; s++)
			for (size_t th = 0; th < nThreads; th++)
				chunks[th][s] = T(0);
		sz = n;
	}
	void add(size_t ix, const T& diff) { chunks[omp_get_thread_num()][ix] += diff; }
	T    get(size_t ix) const
	{
		T ret(0);
		for (size_t th = 0; th < nThreads; th++)
			ret += chunks[th][ix];
		return ret;
	}
};
} // namespace yade
