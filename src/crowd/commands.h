#pragma once
// What a commanded character does (Crowd::moveTo, Crowd::play): walk to its target, re-aiming every
// few metres, and stop there for good; or crossfade to its clip and keep playing it. Commands are
// planned one segment after another from where the character is, so unlike the behaviours' episodes
// they are not closed form: going back in time forgets them.
#include "crowd/behaviours.h"

namespace crowd {

Segment planCommand(Agent& agent, const Segment& current, const PlanContext& context);

}  // namespace crowd
