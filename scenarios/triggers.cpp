#include "scenarios/triggers.hpp"

#include <algorithm>

#include "scenarios/device_values.hpp"

namespace slmp::scenarios {

double operand_value(const devicemodel::DeviceMemory& memory, const Operand& operand) {
    return operand.device ? read_number(memory, *operand.device) : operand.constant;
}

void TriggerSet::scan(const devicemodel::DeviceMemory& memory, double now_ms, std::vector<const Trigger*>& fired) {
    for (auto& s : states_) {
        if (exhausted(s)) continue;
        bool fire = false;
        if (const auto* t = std::get_if<TimeCondition>(&s.trigger->when)) {
            fire = !s.fired_this_time && now_ms >= t->at_ms;
            s.fired_this_time = s.fired_this_time || fire;
        } else if (const auto* c = std::get_if<DeviceCondition>(&s.trigger->when)) {
            if (c->kind == DeviceCondition::Kind::Compare) {
                bool now = compare(operand_value(memory, c->left), c->op, operand_value(memory, c->right));
                if (now && (!s.seen || !s.last)) {
                    s.true_since = now_ms;
                    s.fired_this_time = false;
                }
                fire = now && !s.fired_this_time && now_ms - s.true_since >= s.trigger->for_ms;
                s.fired_this_time = s.fired_this_time || fire;
                s.last = now;
            } else {
                bool bit = operand_value(memory, c->left) != 0;
                bool rising = c->kind == DeviceCondition::Kind::Rising;
                fire = s.seen && bit != s.last && bit == rising;
                s.last = bit;
            }
            s.seen = true;
        }
        if (fire) {
            ++s.fired;
            fired.push_back(s.trigger);
        }
    }
}

void TriggerSet::request(const Incoming& incoming, protocol::EndCode end_code, std::vector<const Trigger*>& fired) {
    const auto& r = incoming.request;
    for (auto& s : states_) {
        const auto* t = std::get_if<TrafficCondition>(&s.trigger->when);
        if (!t || exhausted(s)) continue;
        auto listed = [](const std::vector<std::uint16_t>& list, std::uint16_t v) {
            return list.empty() || std::find(list.begin(), list.end(), v) != list.end();
        };
        if (!r.has_command || !listed(t->commands, r.command) || !listed(t->subcommands, r.subcommand)) continue;
        if (t->client && incoming.peer.address != *t->client) continue;
        if (t->access != Access::Any && (incoming.access() != t->access || end_code != protocol::EndCode::Ok)) continue;
        if (!t->devices.empty() && !touches(r, t->devices)) continue;
        ++s.matches;
        if (t->nth && s.matches != t->nth) continue;
        ++s.fired;
        fired.push_back(s.trigger);
    }
}

}  // namespace slmp::scenarios
