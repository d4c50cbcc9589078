#include "models/mohr_coulomb.hpp"
