// HeapValue<T>: a member that lives on the heap, allocated when first set. A joint holds what only
// some scenes use (the frozen contact of updateTolerance > 0) as one pointer: the per-contact
// objects streamed at every step stay small where the feature is off. Copies copy the value.
#pragma once
#include <memory>

namespace rbsm {

template <class T> class HeapValue {
public:
	HeapValue() = default;
	HeapValue(const HeapValue& o)
	        : p(o.p ? std::make_unique<T>(*o.p) : nullptr)
	{
	}
	HeapValue& operator=(const HeapValue& o)
	{
		if (this != &o) p = o.p ? std::make_unique<T>(*o.p) : nullptr;
		return *this;
	}
	HeapValue(HeapValue&&) noexcept            = default;
	HeapValue& operator=(HeapValue&&) noexcept = default;

	const T* get() const { return p.get(); }
	/// Stores v, in the allocation already held if any.
	void set(const T& v)
	{
		if (p) *p = v;
		else p = std::make_unique<T>(v);
	}
	/// Drops the value (no write when there is none: called at every step of every joint).
	void reset()
	{
		if (p) p.reset();
	}

private:
	std::unique_ptr<T> p;
};

} // namespace rbsm
