// YADE's singletons (ClassFactory, Omega) live in libyade.so: the static `self` pointer of each is
// defined there, so the plugin only declares it and never constructs one.
#pragma once
#include <stdexcept>

template <class T> class Singleton {
protected:
	static T* self;

public:
	static T& instance()
	{
		if (!self) throw std::logic_error("yade-rbsm: a YADE singleton was used before libyade.so created it");
		return *self;
	}
};
