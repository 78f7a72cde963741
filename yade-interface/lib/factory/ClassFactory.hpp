// The class factory of libyade.so: it maps class names to creators and learns which classes a
// plugin library holds. Only the two calls a plugin makes at load time are declared; both are
// non-virtual members exported by libyade.so, so the object's layout is irrelevant here.
#pragma once
#include <lib/base/Math.hpp>
#include <lib/base/Singleton.hpp>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/archive/xml_iarchive.hpp>
#include <boost/archive/xml_oarchive.hpp>
#include <boost/preprocessor.hpp>
#include <boost/serialization/export.hpp> // after every archive type
#include <boost/serialization/factory.hpp>
#include <boost/serialization/map.hpp>
#include <boost/serialization/shared_ptr.hpp>
#include <boost/serialization/vector.hpp>

namespace yade {
class Factorable;

class ClassFactory : public Singleton<ClassFactory> {
public:
	using CreateFn       = Factorable* (*)();
	using CreateSharedFn = shared_ptr<Factorable> (*)();
	using CreatePureFn   = void* (*)();
	bool registerFactorable(std::string name, CreateFn create, CreateSharedFn createShared, CreatePureFn createPureCustom);
	void registerPluginClasses(const char* fileAndClasses[]);
	shared_ptr<Factorable> createShared(std::string name);
};

// Creators of a class, registered with the factory when the library is loaded. The ABI test reads
// the object size of every class from the first instructions of CreatePureCustom<Class>.
#define REGISTER_FACTORABLE(name)                                                                                                                      \
	inline shared_ptr<Factorable> CreateShared##name() { return shared_ptr<name>(new name); }                                                      \
	inline Factorable*            Create##name() { return new name; }                                                                              \
	inline void*                  CreatePureCustom##name() { return new name; }                                                                    \
	const bool registered##name __attribute__((unused))                                                                                           \
	        = ClassFactory::instance().registerFactorable(#name, Create##name, CreateShared##name, CreatePureCustom##name);

// YADE_PLUGIN((A)(B)...): tells the factory which classes this library holds (YADE then registers
// them in Python), and implements their boost::serialization export. Used inside namespace yade.
#define _YADE_PLUGIN_NAME_STR(r, data, name) BOOST_PP_STRINGIZE(name),
#define _YADE_PLUGIN_EXPORT(r, data, name)                                                                                                             \
	BOOST_CLASS_EXPORT_IMPLEMENT(yade::name)                                                                                                       \
	BOOST_SERIALIZATION_FACTORY_0(yade::name)
#define YADE_PLUGIN(plugins)                                                                                                                           \
	}                                                                                                                                              \
	namespace {                                                                                                                                    \
		__attribute__((constructor)) void BOOST_PP_CAT(registerThisPluginClasses_, BOOST_PP_SEQ_HEAD(plugins))()                               \
		{                                                                                                                                      \
			const char* info[] = { __FILE__, BOOST_PP_SEQ_FOR_EACH(_YADE_PLUGIN_NAME_STR, ~, plugins) nullptr };                           \
			::yade::ClassFactory::instance().registerPluginClasses(info);                                                                  \
		}                                                                                                                                      \
	}                                                                                                                                              \
	BOOST_PP_SEQ_FOR_EACH(_YADE_PLUGIN_EXPORT, ~, plugins)                                                                                         \
	namespace yade {

} // namespace yade

// Defined in libyade.so (YADE's SINGLETON_SELF); declared so the plugin refers to that one.
template <> yade::ClassFactory* Singleton<yade::ClassFactory>::self;
