// HeapValue (pkg/rbsm/kernel/HeapValue.hpp): a member held on the heap only once set. Checked: empty
// until set, copies are deep (a joint copied by MemoryOrder owns its frozen contact), set reuses the
// allocation, reset empties.
#include <pkg/rbsm/kernel/FrozenContact.hpp>
#include <pkg/rbsm/kernel/HeapValue.hpp>

#include <gtest/gtest.h>

using rbsm::FrozenContact;
using rbsm::HeapValue;

TEST(HeapValue, EmptyUntilSet)
{
	HeapValue<FrozenContact> h;
	EXPECT_EQ(h.get(), nullptr);
	h.reset();
	EXPECT_EQ(h.get(), nullptr);
	EXPECT_EQ(sizeof(h), sizeof(void*)); // the point of it: one pointer where the feature is off
}

TEST(HeapValue, SetReusesTheAllocationAndResetEmpties)
{
	HeapValue<FrozenContact> h;
	FrozenContact            f;
	f.valid   = true;
	f.refEdge = 3;
	h.set(f);
	const FrozenContact* where = h.get();
	ASSERT_NE(where, nullptr);
	EXPECT_EQ(where->refEdge, 3);
	f.refEdge = 5;
	h.set(f);
	EXPECT_EQ(h.get(), where);
	EXPECT_EQ(h.get()->refEdge, 5);
	h.reset();
	EXPECT_EQ(h.get(), nullptr);
}

TEST(HeapValue, CopiesAreDeep)
{
	HeapValue<FrozenContact> a, empty;
	FrozenContact            f;
	f.valid  = true;
	f.length = 0.25;
	a.set(f);
	HeapValue<FrozenContact> b(a);
	ASSERT_NE(b.get(), nullptr);
	EXPECT_NE(b.get(), a.get());
	EXPECT_EQ(b.get()->length, 0.25);
	f.length = 0.5;
	a.set(f);
	EXPECT_EQ(b.get()->length, 0.25); // b does not share a's value
	b = empty;
	EXPECT_EQ(b.get(), nullptr);
	HeapValue<FrozenContact> c;
	c = a;
	ASSERT_NE(c.get(), nullptr);
	EXPECT_EQ(c.get()->length, 0.5);
}
