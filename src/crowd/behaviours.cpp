#include "crowd/behaviours.h"

#include "crowd/commands.h"
#include "crowd/march.h"
#include "crowd/mill.h"

namespace crowd {

const char* behaviourName(Behaviour behaviour) {
    switch (behaviour) {
        case Behaviour::InPlace: return "in-place";
        case Behaviour::March: return "march";
        case Behaviour::Mill: return "mill";
    }
    return "?";
}

bool parseBehaviour(const std::string& name, Behaviour& behaviour) {
    for (Behaviour b : {Behaviour::InPlace, Behaviour::March, Behaviour::Mill})
        if (name == behaviourName(b)) return behaviour = b, true;
    return false;
}

Segment startBehaviour(Agent& agent, const Segment& first, const PlanContext& context) {
    agent.kind = context.settings.kind;
    agent.home = glm::vec3(first.motion.origin);
    agent.homeHeading = first.motion.origin.w;
    agent.homePhase = first.motion.phase.x;
    if (agent.kind == Behaviour::InPlace || !context.gaits.canTravel()) {
        agent.stage = Agent::Stage::Forever;
        agent.due = Agent::kNever;
        return first;
    }
    if (agent.kind == Behaviour::March) return startMarch(agent, context);
    return enterMillEpisode(agent, 0, context);
}

Segment planNext(Agent& agent, const Segment& current, const PlanContext& context) {
    Segment next;
    if (agent.commanded) next = planCommand(agent, current, context);
    else if (agent.kind == Behaviour::March) next = planMarch(agent, current, context);
    else next = planMill(agent, current, context);
    ++agent.plans;
    return next;
}

bool skipTo(Agent& agent, double time, const PlanContext& context, Segment& segment) {
    if (agent.commanded || !(agent.episodeEnd <= time)) return false;
    if (agent.kind == Behaviour::March) segment = enterMarchCycle(agent, marchCycleAt(time, context), context);
    else segment = enterMillEpisode(agent, millEpisodeAt(time, context), context);
    return true;
}

}  // namespace crowd
