// Functors: function objects called by YADE's dispatchers according to the classes of their
// arguments (YADE's Functor, Functor1D, Functor2D): 80 bytes for Functor in Debian's build.
#pragma once
#include <lib/multimethods/FunctorWrapper.hpp>
#include <lib/serialization/Serializable.hpp>
#include <core/Timing.hpp>

namespace yade {
class Scene;

class Functor : public Serializable {
public:
	virtual std::vector<std::string> getFunctorTypes() const;
	shared_ptr<TimingDeltas>         timingDeltas;
	Scene*                           scene;
	~Functor() override;
	YADE_BUILTIN_CLASS(Functor, Serializable, ((std::string, label, , , "Textual label for this object.")), )
};

template <class DispatchT1, class ResultT, class ArgumentTs> class Functor1D : public Functor, public FunctorWrapper<ResultT, ArgumentTs> {
public:
	using DispatchType1 = DispatchT1;
	virtual std::string get1DFunctorType1() const { throw std::logic_error("Class " + this->getClassName() + " did not use FUNCTOR1D"); }
	std::vector<std::string> getFunctorTypes() const override { return { get1DFunctorType1() }; }
	REGISTER_CLASS_AND_BASE(Functor1D, Functor FunctorWrapper)
};

template <class DispatchT1, class DispatchT2, class ResultT, class ArgumentTs>
class Functor2D : public Functor, public FunctorWrapper<ResultT, ArgumentTs> {
public:
	using DispatchType1 = DispatchT1;
	using DispatchType2 = DispatchT2;
	virtual std::string get2DFunctorType1() const { throw std::logic_error("Class " + this->getClassName() + " did not use FUNCTOR2D"); }
	virtual std::string get2DFunctorType2() const { throw std::logic_error("Class " + this->getClassName() + " did not use FUNCTOR2D"); }
	std::vector<std::string> getFunctorTypes() const override { return { get2DFunctorType1(), get2DFunctorType2() }; }
	REGISTER_CLASS_AND_BASE(Functor2D, Functor FunctorWrapper)
};

// The classes a functor accepts, by name; the dispatchers look these up in the class factory.
#define FUNCTOR1D(type1)                                                                                                                               \
public:                                                                                                                                                \
	std::string get1DFunctorType1() const override { return #type1; }

#define FUNCTOR2D(type1, type2)                                                                                                                        \
public:                                                                                                                                                \
	std::string get2DFunctorType1() const override { return #type1; }                                                                              \
	std::string get2DFunctorType2() const override { return #type2; }
} // namespace yade
