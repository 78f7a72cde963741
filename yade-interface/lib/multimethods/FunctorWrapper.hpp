// The multivirtual call of a functor: go(...) and goReverse(...) for 1 to 7 arguments whose types
// come from the functor's type list. A functor overrides the arity it needs; YADE's dispatchers
// call through these vtable slots, so their number and order are YADE's.
#pragma once
#include <boost/mpl/at.hpp>
#include <boost/mpl/vector.hpp>
#include <stdexcept>
#include <string>

#define TYPELIST_1(T1) ::boost::mpl::vector<T1>
#define TYPELIST_2(T1, T2) ::boost::mpl::vector<T1, T2>
#define TYPELIST_3(T1, T2, T3) ::boost::mpl::vector<T1, T2, T3>
#define TYPELIST_4(T1, T2, T3, T4) ::boost::mpl::vector<T1, T2, T3, T4>
#define TYPELIST_5(T1, T2, T3, T4, T5) ::boost::mpl::vector<T1, T2, T3, T4, T5>
#define TYPELIST_7(T1, T2, T3, T4, T5, T6, T7) ::boost::mpl::vector<T1, T2, T3, T4, T5, T6, T7>

namespace yade {
template <class ResultType, class ArgumentTypeList> class FunctorWrapper {
	using P1 = typename boost::mpl::at_c<ArgumentTypeList, 0>::type;
	using P2 = typename boost::mpl::at_c<ArgumentTypeList, 1>::type;
	using P3 = typename boost::mpl::at_c<ArgumentTypeList, 2>::type;
	using P4 = typename boost::mpl::at_c<ArgumentTypeList, 3>::type;
	using P5 = typename boost::mpl::at_c<ArgumentTypeList, 4>::type;
	using P6 = typename boost::mpl::at_c<ArgumentTypeList, 5>::type;
	using P7 = typename boost::mpl::at_c<ArgumentTypeList, 6>::type;
	[[noreturn]] ResultType error(int n)
	{
		throw std::runtime_error("Multimethods: bad virtual call with " + std::to_string(n) + " arguments (go/goReverse not overridden with these types)");
	}

public:
	FunctorWrapper()          = default;
	virtual ~FunctorWrapper() = default;
	virtual std::string checkOrder() const { return ""; }
	virtual ResultType  go(P1) { error(1); }
	virtual ResultType  go(P1, P2) { error(2); }
	virtual ResultType  go(P1, P2, P3) { error(3); }
	virtual ResultType  go(P1, P2, P3, P4) { error(4); }
	virtual ResultType  go(P1, P2, P3, P4, P5) { error(5); }
	virtual ResultType  go(P1, P2, P3, P4, P5, P6) { error(6); }
	virtual ResultType  go(P1, P2, P3, P4, P5, P6, P7) { error(7); }
	virtual ResultType  goReverse(P1) { error(1); }
	virtual ResultType  goReverse(P1, P2) { error(2); }
	virtual ResultType  goReverse(P1, P2, P3) { error(3); }
	virtual ResultType  goReverse(P1, P2, P3, P4) { error(4); }
	virtual ResultType  goReverse(P1, P2, P3, P4, P5) { error(5); }
	virtual ResultType  goReverse(P1, P2, P3, P4, P5, P6) { error(6); }
	virtual ResultType  goReverse(P1, P2, P3, P4, P5, P6, P7) { error(7); }
};

#define DEFINE_FUNCTOR_ORDER_2D(class1, class2)                                                                                                        \
public:                                                                                                                                                \
	std::string checkOrder() const override { return std::string(#class1) + " " + std::string(#class2); }
} // namespace yade
