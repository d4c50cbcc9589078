#include "models/strain_softening_mohr_coulomb.hpp"
