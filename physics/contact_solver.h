// SPDX-License-Identifier: MIT
// Contact constraints: non-penetration (soft, speculative) and Coulomb friction on two tangents.
#pragma once

#include "physics/body.h"
#include "physics/constraint_parts.h"
#include "physics/contact.h"

#include <vector>

namespace rise::physics {

// `staticBody` stands in for side A of contacts with static geometry: zero velocity, infinite mass.
// PrepareContacts also zeroes the bodies' step deltas that SolveContacts measures separations with.
void PrepareContacts(std::vector<Contact>& contacts, std::vector<Body>& bodies, Body& staticBody,
                     const SolverContext& context);
void WarmStartContacts(std::vector<Contact>& contacts, std::vector<Body>& bodies, Body& staticBody);
// Returns whether a point on static geometry was hard (WorldSettings: hard contacts).
bool SolveContacts(std::vector<Contact>& contacts, std::vector<Body>& bodies, Body& staticBody,
                   const SolverContext& context, bool useBias);

}  // namespace rise::physics
