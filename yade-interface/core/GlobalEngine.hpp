#pragma once
#include <core/Engine.hpp>
