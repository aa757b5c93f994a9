// Handing a breaking contact's correction to its bodies, and to the bodies stuck to them.
//
// A contact that breaks away is owed (mu_s - mu_k)·N·s for the kinetic friction that has acted
// for s since the limit was crossed inside the step (treatment_stick_slip.cpp). It is paid at
// the start of the next step, as one impulse. A body alone takes it as the velocity it should
// have. A body that carries another on a stuck contact (a block on a block, the bottom one
// breaking away from the floor) does not move alone: over those s seconds the two moved as one,
// the top one pulled along by its friction. Given to the bottom block alone, the correction
// asks the top contact to pass the top block its share within the next step, on top of the
// jump in acceleration that breaking away brings: up to 2.5 times that jump, so a top block
// whose mu_s was below about 2.5 × the floor's (mu_s - mu_k) slipped at breakaway although it
// could keep up (top 0.15/0.1 on a 0.3/0.2 floor slipped at 8.85 N, where theory says 10.3 N).
// So the correction is shared out through stuck contacts as the rigid link they are: every body
// so joined takes the same change of velocity, each link carrying the share of the bodies
// beyond it, as long as that share, spread over s, keeps the link's friction within its
// static limit. A link that could not carry it is left to the solver, which then finds the
// link slipping, as it should. A body stuck to a fixed or driven body (which no impulse moves)
// that can carry the whole correction passes it on there.
#include <algorithm>
#include <cmath>

#include "physics/contact_mechanics.h"
#include "physics/friction_listener.h"

namespace frictionlab {
namespace {

// Only links whose surfaces lie along the broken contact's (to within 2.6°) carry a share: a
// share across a tilted link would need its normal impulse too, which may not pull.
constexpr float parallel_links = 0.999f;
// How many bodies a share reaches: a stack, not a pile.
constexpr std::size_t most_sharing = 16;

}  // namespace

void FrictionListener::share_with_stuck(const b2Contact* broken, b2Body* body, const b2Vec2& push, double span,
                                        std::vector<Share>* shares) {
  // The bodies reached through stuck links, breadth first: each with the body it was reached
  // from and the link's record.
  struct Member {
    b2Body* body;
    int parent;
    const ContactRecord* link;
    bool left_out;
  };
  std::vector<Member> members{{body, -1, nullptr, false}};
  const b2Vec2 along = push;
  // Whether `link` can carry `carried` (N·s on `to`) over span within its static limit.
  auto carries = [&](const ContactRecord& link, const b2Body* to, const b2Vec2& carried) {
    const double added = link.side(to) * b2Dot(carried, link.tangent());
    const double limit = breakaway_coefficient(pairs_.pair_at(link.identity.pair_index)) * link.solver.normal_force;
    return std::abs(link.solver.friction_force + added / span) <= limit;
  };
  for (std::size_t i = 0; i < members.size() && members.size() < most_sharing; ++i) {
    for (b2ContactEdge* edge = members[i].body->GetContactList(); edge != nullptr; edge = edge->next) {
      if (edge->contact == broken || !edge->contact->IsTouching()) continue;
      const ContactRecord* link = record(edge->contact);
      if (link == nullptr || link->identity.unpaired || link->listener.fresh ||
          link->friction.state != ContactState::sticking || link->solver.normal_force <= 0.0 ||
          rule_at(link->identity.pair_index).treatment != FrictionTreatment::stick_slip) {
        continue;
      }
      if (std::abs(b2Dot(link->tangent(), along)) < parallel_links * along.Length()) continue;
      b2Body* other = edge->other;
      if (std::any_of(members.begin(), members.end(), [&](const Member& m) { return m.body == other; })) continue;
      if (other->GetType() != b2_dynamicBody) {
        // Held by something no impulse moves: if the link can take it all, it does.
        if (i == 0 && carries(*link, body, push)) return;
        // Further out, that body is not free to follow: its branch stays with the solver.
        members[i].left_out = i > 0;
        continue;
      }
      members.push_back({other, static_cast<int>(i), link, false});
    }
  }
  // Leave out the branches that cannot carry their share, until every link left can.
  std::vector<double> beyond(members.size());
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t j = 1; j < members.size(); ++j) {
      if (members[static_cast<std::size_t>(members[j].parent)].left_out) members[j].left_out = true;
    }
    double total = 0.0;
    for (std::size_t j = members.size(); j-- > 0;) {
      beyond[j] = members[j].left_out ? 0.0 : members[j].body->GetMass();
    }
    for (std::size_t j = members.size(); j-- > 1;) beyond[static_cast<std::size_t>(members[j].parent)] += beyond[j];
    total = beyond[0];
    for (std::size_t j = 1; j < members.size() && !changed; ++j) {
      if (members[j].left_out) continue;
      const b2Vec2 carried = static_cast<float>(beyond[j] / total) * push;
      if (!carries(*members[j].link, members[j].body, carried)) {
        members[j].left_out = true;
        changed = true;
      }
    }
    if (!changed) {
      for (std::size_t j = 0; j < members.size(); ++j) {
        if (!members[j].left_out || j == 0) {
          shares->push_back({members[j].body, static_cast<float>(members[j].body->GetMass() / total) * push});
        }
      }
    }
  }
}

void FrictionListener::apply_breakaway(b2Contact* contact, ContactRecord& r) {
  const b2Vec2 t = r.tangent();
  // A group's correction is its body's, through the centres like a face's.
  const bool face = r.solver.point_count == 2 || r.listener.siblings > 0;
  const double owed = r.breakaway.impulse;
  const double span = r.breakaway.span;
  r.breakaway.impulse = 0.0;
  r.breakaway.span = 0.0;
  const b2Vec2 push = static_cast<float>(owed) * t;  // on B; A takes -push
  std::vector<Share> shares;
  bool alone = true;  // each side's share is all its own
  if (span > 0.0) {
    for (b2Body* side : {r.identity.body_b, r.identity.body_a}) {
      if (side->GetType() != b2_dynamicBody) continue;
      const std::size_t first = shares.size();
      share_with_stuck(contact, side, side == r.identity.body_b ? push : -push, span, &shares);
      alone = alone && shares.size() == first + 1;
    }
  }
  if (alone) {
    const double mass = contact_mass(r.identity.body_a, r.identity.body_b, face, r.solver.point, t);
    const double v = sliding_speed(r.identity.body_a, r.identity.body_b, face, r.solver.point, t);
    apply_tangential_impulse(r.identity.body_a, r.identity.body_b, r.solver.point, t, static_cast<float>(owed), face);
    if (mass > 0.0) work_.friction += owed * (v + 0.5 * owed / mass);
    return;
  }
  // The books take what the shares did to the bodies' kinetic energy, the links' transfers
  // included: the friction work of the correction, whoever carried it.
  double before = 0.0, after = 0.0;
  for (const Share& s : shares) before += kinetic_energy(s.body);
  for (const Share& s : shares) {
    if (face || (s.body != r.identity.body_a && s.body != r.identity.body_b)) {
      s.body->ApplyLinearImpulseToCenter(s.push, true);
    } else {
      s.body->ApplyLinearImpulse(s.push, r.solver.point, true);
    }
  }
  for (const Share& s : shares) after += kinetic_energy(s.body);
  work_.friction += after - before;
}

}  // namespace frictionlab
