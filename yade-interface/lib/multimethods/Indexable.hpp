// Class indices for YADE's multiple dispatch (functors chosen by the classes of their arguments).
// Every top-level indexable (Shape, Bound, IGeom, IPhys, Material, State) owns a counter in
// libyade.so; a plugin class takes the next free index of its kin when first constructed.
#pragma once
#include <boost/scoped_ptr.hpp>
#include <stdexcept>
#include <string>

namespace yade {

class Indexable {
protected:
	void createIndex()
	{
		int& index = modifyClassIndex();
		if (index == -1) {
			index = getMaxCurrentlyUsedClassIndexOfKin() + 1;
			incrementMaxCurrentlyUsedClassIndexOfKin();
		}
	}
	// The virtual functions below are in YADE's order (the vtable slots depend on it). YADE defines
	// them inline and does not export Indexable's vtable, so they are defined here the same way.
	virtual void incrementMaxCurrentlyUsedClassIndexOfKin() { notOverridden(__PRETTY_FUNCTION__); }
	virtual int& modifyClassIndex() { notOverridden(__PRETTY_FUNCTION__); }

public:
	Indexable()          = default;
	virtual ~Indexable() = default;
	virtual const int& getClassIndex() const { notOverridden(__PRETTY_FUNCTION__); }
	virtual const int& getBaseClassIndex(int) const { notOverridden(__PRETTY_FUNCTION__); }
	virtual const int& getMaxCurrentlyUsedClassIndexOfKin() const { notOverridden(__PRETTY_FUNCTION__); }

private:
	[[noreturn]] static void notOverridden(const char* fn)
	{
		throw std::logic_error(std::string("Indexable class did not declare its class index (REGISTER_CLASS_INDEX): ") + fn);
	}
};

// For a class that is a dimension of a dispatch matrix (a Shape, an IGeom, ...): its own index,
// taken from the counter of its top-level indexable `BaseClass` chain.
#define REGISTER_CLASS_INDEX(SomeClass, BaseClass)                                                                                                     \
private:                                                                                                                                               \
	static int& modifyClassIndexStatic()                                                                                                           \
	{                                                                                                                                              \
		static int index = -1;                                                                                                                 \
		return index;                                                                                                                          \
	}                                                                                                                                              \
                                                                                                                                                       \
protected:                                                                                                                                             \
	int& modifyClassIndex() override { return modifyClassIndexStatic(); }                                                                          \
                                                                                                                                                       \
public:                                                                                                                                                \
	static const int& getClassIndexStatic() { return modifyClassIndexStatic(); }                                                                   \
	const int&        getClassIndex() const override { return getClassIndexStatic(); }                                                             \
	const int&        getBaseClassIndex(int depth) const override                                                                                  \
	{                                                                                                                                              \
		static boost::scoped_ptr<BaseClass> baseClass(new BaseClass);                                                                          \
		if (depth == 1) return baseClass->getClassIndex();                                                                                     \
		return baseClass->getBaseClassIndex(--depth);                                                                                          \
	}

// The overrides a top-level indexable declares (REGISTER_INDEX_COUNTER in YADE); their definitions
// and the counters they use are Debian's.
// The order of the declarations fixes the order of the slots these overrides get in the primary
// vtable of every class below (YADE's REGISTER_INDEX_COUNTER order).
#define YADE_DECLARE_INDEX_COUNTER                                                                                                                     \
protected:                                                                                                                                             \
	int& modifyClassIndex() override;                                                                                                              \
                                                                                                                                                       \
public:                                                                                                                                                \
	const int& getClassIndex() const override;                                                                                                     \
	const int& getBaseClassIndex(int) const override;                                                                                              \
	const int& getMaxCurrentlyUsedClassIndexOfKin() const override;                                                                                \
                                                                                                                                                       \
protected:                                                                                                                                             \
	void incrementMaxCurrentlyUsedClassIndexOfKin() override;                                                                                      \
                                                                                                                                                       \
public:

// The overrides of a built-in class that used REGISTER_CLASS_INDEX (Aabb, ...): Debian's.
#define YADE_DECLARE_CLASS_INDEX                                                                                                                       \
protected:                                                                                                                                             \
	int& modifyClassIndex() override;                                                                                                              \
                                                                                                                                                       \
public:                                                                                                                                                \
	const int& getClassIndex() const override;                                                                                                     \
	const int& getBaseClassIndex(int) const override;

} // namespace yade
