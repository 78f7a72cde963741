// Root of YADE's class hierarchy: a polymorphic object that knows its class name and its base's.
// Layout: vptr + boost::enable_shared_from_this (a weak_ptr) = 24 bytes.
#pragma once
#include <lib/base/Math.hpp>
#include <lib/factory/ClassFactory.hpp>
#include <boost/enable_shared_from_this.hpp>

namespace yade {

// getClassName / getBaseClassName / getBaseClassNumber for a class; `bases` may name several
// classes separated by spaces (YADE's functors name "Functor FunctorWrapper").
#define REGISTER_CLASS_NAME(cn)                                                                                                                        \
public:                                                                                                                                                \
	std::string getClassName() const override { return #cn; }

#define REGISTER_BASE_CLASS_NAME(bcn)                                                                                                                  \
public:                                                                                                                                                \
	std::string getBaseClassName(unsigned int i = 0) const override                                                                                \
	{                                                                                                                                              \
		const auto names = ::yade::detail::splitClassNames(#bcn);                                                                              \
		return i < names.size() ? names[i] : std::string();                                                                                    \
	}                                                                                                                                              \
	int getBaseClassNumber() const override { return int(::yade::detail::splitClassNames(#bcn).size()); }

#define REGISTER_CLASS_AND_BASE(cn, bcn)                                                                                                               \
	REGISTER_CLASS_NAME(cn)                                                                                                                        \
	REGISTER_BASE_CLASS_NAME(bcn)

namespace detail {
	inline std::vector<std::string> splitClassNames(const char* names)
	{
		std::vector<std::string> out;
		std::string              cur;
		for (const char* c = names; *c; ++c) {
			if (*c == ' ') {
				if (!cur.empty()) out.push_back(cur);
				cur.clear();
			} else
				cur += *c;
		}
		if (!cur.empty()) out.push_back(cur);
		return out;
	}
}

class Factorable : public boost::enable_shared_from_this<Factorable> {
public:
	Factorable() = default;
	virtual ~Factorable();
	virtual std::string getBaseClassName(unsigned int = 0) const;
	virtual int         getBaseClassNumber() const;
	virtual std::string getClassName() const;
};

} // namespace yade
