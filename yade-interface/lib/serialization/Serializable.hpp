// Serializable: a YADE object with attributes that are saved (boost::serialization) and seen from
// Python. The class macros (YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY and friends) have YADE's names and
// meaning; they are implemented here. An attribute is the tuple
//     ((type, name, default, flags, "docstring"))
// with flags from yade::Attr (noSave, readonly, triggerPostLoad, hidden), possibly empty.
#pragma once
#include <lib/base/Math.hpp>
#include <lib/factory/Factorable.hpp>
#include <lib/pyutil/raw_constructor.hpp>

#include <boost/lexical_cast.hpp>
#include <boost/preprocessor.hpp>
#include <boost/python.hpp>
#include <boost/serialization/base_object.hpp>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace yade {

// Hooks called around (de)serialization; a class overloads e.g. postLoad(MyClass&) to refresh
// derived data after loading or after an attribute is set from Python with triggerPostLoad.
template <typename T> void preLoad(T&) { }
template <typename T> void postLoad(T&) { }
template <typename T> void preSave(T&) { }
template <typename T> void postSave(T&) { }

namespace Attr {
	enum flags { noSave = 1, readonly = 2, triggerPostLoad = 4, hidden = 8, noResize = 16 };
}

class Serializable : public Factorable {
public:
	template <class ArchiveT> void serialize(ArchiveT&, unsigned int) { }
	template <class DerivedT> const DerivedT& cast() const { return *static_cast<const DerivedT*>(this); }
	template <class DerivedT> DerivedT&       cast() { return *static_cast<DerivedT*>(this); }

	Serializable() = default;
	~Serializable() override;

	void pyUpdateAttrs(const boost::python::dict& d);

	// YADE's order of the virtual functions (vtable slots after Factorable's).
	virtual void                  pySetAttr(const std::string& key, const boost::python::object& value);
	virtual boost::python::dict   pyDict() const;
	virtual boost::python::dict   pyDictCustom() const;
	virtual void                  callPostLoad();
	virtual void                  checkPyClassRegistersItself(const std::string& thisClassName) const;
	virtual void                  pyRegisterClass(boost::python::object scope);
	virtual void                  pyHandleCustomCtorArgs(boost::python::tuple& args, boost::python::dict& kw);

	std::string getClassName() const override;
	std::string getBaseClassName(unsigned int = 0) const override;
	int         getBaseClassNumber() const override;
};

// Construct from Python keyword arguments: Class(attr=value, ...).
template <typename T> shared_ptr<T> Serializable_ctor_kwAttrs(boost::python::tuple& args, boost::python::dict& kw)
{
	shared_ptr<T> instance(new T);
	instance->pyHandleCustomCtorArgs(args, kw);
	if (boost::python::len(args) > 0)
		throw std::runtime_error(
		        instance->getClassName() + " takes keyword arguments only (attribute=value), not "
		        + boost::lexical_cast<std::string>(boost::python::len(args)) + " positional argument(s).");
	if (boost::python::len(kw) > 0) {
		instance->pyUpdateAttrs(kw);
		instance->callPostLoad();
	}
	return instance;
}

namespace detail {
	// Eigen vectors and matrices are returned by reference, so `b.state.vel[0] = 1` changes the
	// body; everything else is returned by value (YADE's py_wrap_ref).
	template <class T> struct ReturnsReference : std::false_type { };
	template <> struct ReturnsReference<Vector2r> : std::true_type { };
	template <> struct ReturnsReference<Vector2i> : std::true_type { };
	template <> struct ReturnsReference<Vector3r> : std::true_type { };
	template <> struct ReturnsReference<Vector3i> : std::true_type { };
	template <> struct ReturnsReference<Quaternionr> : std::true_type { };
	template <> struct ReturnsReference<Matrix3r> : std::true_type { };

	// Set an attribute whose postLoad checks it; a value that postLoad rejects is undone, so a
	// failed assignment from Python leaves the object (and the scene) as it was.
	// (Member may belong to a base class B of C: RbsmMat checks Material's density this way.)
	template <class C, class B, class T, T B::*Member> void setThenPostLoad(C& instance, const T& value)
	{
		T previous       = instance.*Member;
		instance.*Member = value;
		try {
			instance.callPostLoad();
		} catch (...) {
			instance.*Member = previous;
			try {
				instance.callPostLoad(); // refresh what postLoad derives from the restored value
			} catch (...) {
			}
			throw;
		}
	}

	// updateAttrs of the plugin's classes: all the values of d or none. YADE's own
	// Serializable::pyUpdateAttrs sets every value, then calls postLoad, and keeps a value that
	// postLoad refuses; here every value set is put back (in reverse order) before the error goes on.
	template <class C> void updateAttrsOrNothing(C& instance, const boost::python::dict& d)
	{
		namespace py = boost::python;
		const py::dict                                   before = instance.pyDict();
		const py::list                                   keys   = d.keys();
		std::vector<std::pair<std::string, py::object>> saved;
		try {
			for (py::ssize_t i = 0; i < py::len(keys); i++) {
				const std::string key = py::extract<std::string>(keys[i]);
				if (before.has_key(key)) saved.emplace_back(key, before[key]);
				instance.pySetAttr(key, d[keys[i]]);
			}
			instance.callPostLoad();
		} catch (...) {
			for (auto it = saved.rbegin(); it != saved.rend(); ++it) {
				try {
					instance.pySetAttr(it->first, it->second);
				} catch (...) {
				}
			}
			try {
				instance.callPostLoad(); // refresh what postLoad derives from the restored values
			} catch (...) {
			}
			throw;
		}
	}

	// Expose one attribute to Python according to its flags.
	template <class PyClass, class C, class T, T C::*Member> void defineAttribute(PyClass& cls, const char* name, int flags, std::string doc)
	{
		namespace py = boost::python;
		if (flags & Attr::hidden) return;
		doc += " :yattrflags:`" + boost::lexical_cast<std::string>(flags) + "` ";
		const bool readonly = flags & Attr::readonly, post = flags & Attr::triggerPostLoad;
		using byValue       = py::return_value_policy<py::return_by_value>;
		if constexpr (ReturnsReference<T>::value) {
			if (readonly) cls.def_readonly(name, Member, doc.c_str());
			else if (post)
				cls.add_property(name, py::make_getter(Member), &setThenPostLoad<C, C, T, Member>, doc.c_str());
			else
				cls.def_readwrite(name, Member, doc.c_str());
		} else {
			if (readonly) cls.add_property(name, py::make_getter(Member, byValue()), doc.c_str());
			else if (post)
				cls.add_property(name, py::make_getter(Member, byValue()), &setThenPostLoad<C, C, T, Member>, doc.c_str());
			else
				cls.add_property(name, py::make_getter(Member, byValue()), py::make_setter(Member, byValue()), doc.c_str());
		}
	}
} // namespace detail

// ---- attribute tuple accessors ----
#define _YADE_ATTR_TYPE(a) BOOST_PP_TUPLE_ELEM(5, 0, a)
#define _YADE_ATTR_NAME(a) BOOST_PP_TUPLE_ELEM(5, 1, a)
#define _YADE_ATTR_DEFAULT(a) BOOST_PP_TUPLE_ELEM(5, 2, a)
#define _YADE_ATTR_FLAGS(a) (BOOST_PP_TUPLE_ELEM(5, 3, a) + 0) /* +0: the flags may be empty */
#define _YADE_ATTR_DOC(a) BOOST_PP_TUPLE_ELEM(5, 4, a)
#define _YADE_ATTR_NAME_STR(a) BOOST_PP_STRINGIZE(_YADE_ATTR_NAME(a))

// ---- pieces generated for every attribute ----
#define _YADE_ATTR_DECLARE(r, data, a) _YADE_ATTR_TYPE(a) _YADE_ATTR_NAME(a);
// The constructor's initializer list from (name, value) pairs: the inits first, then every
// attribute with its default; commas between items only, and no colon when there is nothing.
#define _YADE_ATTR_INIT_PAIR(r, data, a) ((_YADE_ATTR_NAME(a), _YADE_ATTR_DEFAULT(a)))
#define _YADE_INIT_ITEM(r, last, i, p) BOOST_PP_TUPLE_ELEM(2, 0, p)(BOOST_PP_TUPLE_ELEM(2, 1, p)) BOOST_PP_COMMA_IF(BOOST_PP_NOT_EQUAL(last, i))
#define _YADE_INIT_LIST_OF(pairs)                                                                                                                      \
	BOOST_PP_IF(BOOST_PP_SEQ_SIZE(pairs), :, ) BOOST_PP_SEQ_FOR_EACH_I(_YADE_INIT_ITEM, BOOST_PP_DEC(BOOST_PP_SEQ_SIZE(pairs)), pairs)
#define _YADE_INIT_LIST(inits, attrs) _YADE_INIT_LIST_OF(inits BOOST_PP_SEQ_FOR_EACH(_YADE_ATTR_INIT_PAIR, ~, attrs))
#define _YADE_ATTR_ARCHIVE(r, data, a)                                                                                                                 \
	if (!(_YADE_ATTR_FLAGS(a) & ::yade::Attr::noSave)) ar& boost::serialization::make_nvp(_YADE_ATTR_NAME_STR(a), _YADE_ATTR_NAME(a));
#define _YADE_ATTR_PYSET(r, data, a)                                                                                                                   \
	if (key == _YADE_ATTR_NAME_STR(a)) {                                                                                                           \
		_YADE_ATTR_NAME(a) = boost::python::extract<decltype(_YADE_ATTR_NAME(a))>(value);                                                      \
		return;                                                                                                                                \
	}
#define _YADE_ATTR_PYDICT(r, data, a)                                                                                                                  \
	if (!(_YADE_ATTR_FLAGS(a) & ::yade::Attr::hidden)) ret[_YADE_ATTR_NAME_STR(a)] = boost::python::object(_YADE_ATTR_NAME(a));
#define _YADE_ATTR_PYDEF(r, thisClass, a)                                                                                                              \
	::yade::detail::defineAttribute<decltype(_classObj), thisClass, decltype(thisClass::_YADE_ATTR_NAME(a)), &thisClass::_YADE_ATTR_NAME(a)>(     \
	        _classObj,                                                                                                                             \
	        _YADE_ATTR_NAME_STR(a),                                                                                                                \
	        _YADE_ATTR_FLAGS(a),                                                                                                                   \
	        _YADE_ATTR_DOC(a) " :ydefault:`" BOOST_PP_STRINGIZE(_YADE_ATTR_DEFAULT(a)) "` :yattrtype:`" BOOST_PP_STRINGIZE(_YADE_ATTR_TYPE(a)) "`");

// Saved members: the base class first (named like the base), then every attribute without noSave,
// in declaration order; YADE's pre/post hooks around them.
#define _YADE_SERIALIZE_BODY(baseClass, attrs)                                                                                                         \
	friend class boost::serialization::access;                                                                                                     \
                                                                                                                                                       \
private:                                                                                                                                               \
	template <class ArchiveT> void serialize(ArchiveT& ar, unsigned int)                                                                          \
	{                                                                                                                                              \
		ar& boost::serialization::make_nvp(BOOST_PP_STRINGIZE(baseClass), boost::serialization::base_object<baseClass>(*this));               \
		if (ArchiveT::is_loading::value) preLoad(*this);                                                                                       \
		else                                                                                                                                   \
			preSave(*this);                                                                                                                \
		BOOST_PP_SEQ_FOR_EACH(_YADE_ATTR_ARCHIVE, ~, attrs)                                                                                    \
		if (ArchiveT::is_loading::value) postLoad(*this);                                                                                      \
		else                                                                                                                                   \
			postSave(*this);                                                                                                               \
	}

// ---- plugin classes: everything generated here ----
#define YADE_CLASS_BASE_DOC_ATTRS_DEPREC_INIT_CTOR_PY(thisClass, baseClass, docString, attrs, deprec, inits, ctor, extras)                           \
public:                                                                                                                                                \
	BOOST_PP_SEQ_FOR_EACH(_YADE_ATTR_DECLARE, ~, attrs)                                                                                            \
	thisClass() _YADE_INIT_LIST(inits, attrs)                                                                                                     \
	{                                                                                                                                              \
		ctor;                                                                                                                                  \
	}                                                                                                                                              \
	_YADE_SERIALIZE_BODY(baseClass, attrs)                                                                                                         \
public:                                                                                                                                                \
	void pySetAttr(const std::string& key, const boost::python::object& value) override                                                           \
	{                                                                                                                                              \
		BOOST_PP_SEQ_FOR_EACH(_YADE_ATTR_PYSET, ~, attrs)                                                                                      \
		baseClass::pySetAttr(key, value);                                                                                                      \
	}                                                                                                                                              \
	boost::python::dict pyDict() const override                                                                                                    \
	{                                                                                                                                              \
		boost::python::dict ret;                                                                                                               \
		BOOST_PP_SEQ_FOR_EACH(_YADE_ATTR_PYDICT, ~, attrs)                                                                                     \
		ret.update(this->pyDictCustom());                                                                                                      \
		ret.update(baseClass::pyDict());                                                                                                       \
		return ret;                                                                                                                            \
	}                                                                                                                                              \
	void callPostLoad() override                                                                                                                   \
	{                                                                                                                                              \
		baseClass::callPostLoad();                                                                                                             \
		postLoad(*this);                                                                                                                       \
	}                                                                                                                                              \
	REGISTER_CLASS_AND_BASE(thisClass, baseClass)                                                                                                  \
	void pyRegisterClass(boost::python::object _scope) override                                                                                    \
	{                                                                                                                                              \
		checkPyClassRegistersItself(#thisClass);                                                                                               \
		boost::python::scope             thisScope(_scope);                                                                                    \
		boost::python::docstring_options docopt;                                                                                               \
		docopt.enable_all();                                                                                                                   \
		docopt.disable_cpp_signatures();                                                                                                       \
		boost::python::class_<thisClass, shared_ptr<thisClass>, boost::python::bases<baseClass>, boost::noncopyable> _classObj(               \
		        #thisClass, docString);                                                                                                        \
		_classObj.def("__init__", ::yade::raw_constructor(::yade::Serializable_ctor_kwAttrs<thisClass>));                                      \
		_classObj.def("updateAttrs", &::yade::detail::updateAttrsOrNothing<thisClass>, boost::python::arg("d"),                             \
		              "Set the attributes of dict *d*, all or none: a value refused (ValueError) leaves every attribute as it was.");      \
		BOOST_PP_SEQ_FOR_EACH(_YADE_ATTR_PYDEF, thisClass, attrs)                                                                              \
		(void)_classObj extras;                                                                                                                \
	}

#define YADE_CLASS_BASE_DOC_ATTRS_INIT_CTOR_PY(klass, base, doc, attrs, inits, ctor, py)                                                             \
	YADE_CLASS_BASE_DOC_ATTRS_DEPREC_INIT_CTOR_PY(klass, base, doc, attrs, , inits, ctor, py)
#define YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(klass, base, doc, attrs, ctor, py) YADE_CLASS_BASE_DOC_ATTRS_INIT_CTOR_PY(klass, base, doc, attrs, , ctor, py)
#define YADE_CLASS_BASE_DOC_ATTRS_CTOR(klass, base, doc, attrs, ctor) YADE_CLASS_BASE_DOC_ATTRS_INIT_CTOR_PY(klass, base, doc, attrs, , ctor, )
#define YADE_CLASS_BASE_DOC_ATTRS(klass, base, doc, attrs) YADE_CLASS_BASE_DOC_ATTRS_INIT_CTOR_PY(klass, base, doc, attrs, , , )
#define YADE_CLASS_BASE_DOC(klass, base, doc) YADE_CLASS_BASE_DOC_ATTRS_INIT_CTOR_PY(klass, base, doc, , , , )

// Class factory registration and boost::serialization export key; used inside namespace yade.
#define REGISTER_SERIALIZABLE(name)                                                                                                                    \
	REGISTER_FACTORABLE(name)                                                                                                                      \
	}                                                                                                                                              \
	BOOST_CLASS_EXPORT_KEY(yade::name)                                                                                                             \
	namespace yade {

// ---- YADE's own classes: layout, constructor and archive format here, the rest is Debian's ----
// The attributes are declared (with YADE's defaults) and serialized exactly as YADE does; the
// virtual functions that YADE's macro generates are only declared, so the plugin calls the
// definitions exported by libyade.so.
#define YADE_BUILTIN_CLASS(thisClass, baseClass, attrs, ctor) YADE_BUILTIN_CLASS_INIT(thisClass, baseClass, attrs, , ctor)

// A class whose constructor also binds members before the attributes (State's pos, ori): inits.
#define YADE_BUILTIN_CLASS_INIT(thisClass, baseClass, attrs, inits, ctor)                                                                             \
public:                                                                                                                                                \
	BOOST_PP_SEQ_FOR_EACH(_YADE_ATTR_DECLARE, ~, attrs)                                                                                            \
	thisClass() _YADE_INIT_LIST(inits, attrs)                                                                                                     \
	{                                                                                                                                              \
		ctor;                                                                                                                                  \
	}                                                                                                                                              \
	_YADE_SERIALIZE_BODY(baseClass, attrs)                                                                                                         \
public:                                                                                                                                                \
	YADE_DECLARE_SERIALIZABLE_OVERRIDES

#define YADE_DECLARE_SERIALIZABLE_OVERRIDES                                                                                                            \
	void                pySetAttr(const std::string& key, const boost::python::object& value) override;                                            \
	boost::python::dict pyDict() const override;                                                                                                   \
	void                callPostLoad() override;                                                                                                   \
	std::string         getClassName() const override;                                                                                             \
	std::string         getBaseClassName(unsigned int = 0) const override;                                                                         \
	int                 getBaseClassNumber() const override;                                                                                       \
	void                pyRegisterClass(boost::python::object scope) override;

} // namespace yade
