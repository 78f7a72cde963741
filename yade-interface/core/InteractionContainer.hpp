// The interactions of a scene (O.interactions); iterating gives real and potential ones.
#pragma once
#include <core/BodyContainer.hpp>
#include <core/Interaction.hpp>

namespace yade {
class InteractionContainer : public Serializable {
	using ContainerT = std::vector<shared_ptr<Interaction>>;
	ContainerT                        linIntrs;
	ContainerT                        sortedIntrs;
	const BodyContainer::ContainerT*  bodies;
	size_t                            currSize;
	shared_ptr<Interaction>           empty;
	std::vector<shared_ptr<Interaction>> interaction;

public:
	bool       dirty;
	std::mutex drawloopmutex;
	bool       serializeSorted;
	long       iterColliderLastRun;

	using iterator       = ContainerT::iterator;
	using const_iterator = ContainerT::const_iterator;
	iterator       begin() { return linIntrs.begin(); }
	iterator       end() { return linIntrs.end(); }
	const_iterator begin() const { return linIntrs.begin(); }
	const_iterator end() const { return linIntrs.end(); }
	size_t         size() const { return currSize; }
	const shared_ptr<Interaction>& find(Body::id_t id1, Body::id_t id2); // exported by libyade.so
	void                           requestErase(const shared_ptr<Interaction>& I);
	bool                           insert(const shared_ptr<Interaction>& I); // exported by libyade.so
	void                           clear();                                  // exported by libyade.so

	InteractionContainer() = delete;
	~InteractionContainer() override;
	YADE_DECLARE_SERIALIZABLE_OVERRIDES
};
} // namespace yade
