// impacts.h — impacts resolved at their time of impact, one after another.
//
// The soft step stops a closing contact where its speculative gap closes and the restitution
// pass bounces it at the end of the step, off the approach speed it had at the start. That
// bounce is late by the time left in the step and off by what gravity added before the impact:
// a bouncing ball loses centimetres of height per bounce. And a touching row (Newton's cradle)
// is one simultaneous contact to it, so the striker's momentum spreads over the row.
//
// Before the substeps, Impacts finds each contact's time of impact t* in the step from free
// flight (gravity on bodies no contact supported last step) and applies Newton's impact law
// there: the normal velocity becomes −e times its value at t*, with Coulomb friction up to μ
// times that impulse. Impacts are taken in time order, ties in contact order; an impact changes
// its two bodies' later flight, which may bring a touching neighbour's impact forward to the same
// instant, so a row passes the impulse from ball to ball, as a real cradle does.
//
// A velocity change Δv at t* is given to the body from the start of the step (the substeps then
// integrate the flight after the impact) and its position is corrected by −Δv·t* at the end:
//   x(dt) = x0 + v0·t* + ½·g·t*² + (v0 + g·t* + Δv)·(dt − t*) + ½·g·(dt − t*)²
//         = x0 + (v0 + Δv)·dt + ½·g·dt² − Δv·t*,
// exactly where free flight with a bounce at t* ends. Each contact's separation is shifted to
// match meanwhile (Contact::shift), so that the solver sees where the bodies really go.
//
// Contacts that bore load in the last step (warm started with a normal impulse: a ball resting
// in a pile) are left to the solver, which shares a blow among them at once, and to the
// restitution pass. Only impacts faster than bounceThreshold() are events; slower ones are the
// solver's (they do not bounce). A chain that will not end (a sphere pinned between two others, e =
// 1) stops at maxImpacts per contact; the solver and the restitution pass take what is left.
#pragma once

#include "contact_solver.h"

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace mb {

class Impacts {
public:
    // Resolves this step's impacts in ctx.contacts (separations at the start of the step) and
    // changes the bodies' velocities and spins. Returns the number of impacts.
    int resolve(SolverContext& ctx);
    // Adds the position corrections of the last resolve() to the bodies' pos and delta, and takes
    // Contact::shift back out of the contacts' separations.
    void correctPositions(std::vector<PhysicsBody>& bodies, std::vector<Contact>& contacts) const;
    // A body's position correction: where it truly is, less where the substeps have it.
    glm::dvec3 offset(int body) const;

private:
    struct Event {
        double time;
        int contact;
        std::uint32_t stamp;  // the contact's stamp when this was found; stale when it differs
        bool operator>(const Event& o) const {
            return time > o.time || (time == o.time && contact > o.contact);
        }
    };
    void schedule(const SolverContext& ctx, int contact, double now);
    void hit(SolverContext& ctx, const Contact& c, double t);
    void linkBodies(const SolverContext& ctx);
    void shiftSeparations(std::vector<Contact>& contacts);

    std::vector<glm::dvec3> offset_;    // per body: position correction, −Σ Δv·t*
    std::vector<glm::dvec3> accel_;     // per body: free-flight acceleration this step
    std::vector<char> hit_;             // per body: an impact moved it this step
    std::vector<int> moved_;            // the bodies hit, the only ones with an offset
    std::vector<int> shifted_;          // the contacts of those, the only ones with a shift
    std::vector<std::uint32_t> stamp_;  // per contact
    std::vector<int> count_;            // per contact: impacts this step
    std::vector<Event> heap_;           // min-heap on (time, contact)
    std::vector<int> open_;             // the contacts that bore no load last step
    std::vector<int> due_;              // scratch: those of them that may impact from the start
    std::vector<int> first_,
        links_;              // per body: its open contacts, links_[first_[i] .. first_[i + 1])
    std::vector<int> next_;  // scratch for linkBodies
    bool linked_ = false;
    bool any_ = false;  // an impact happened: offsets to apply
};

}  // namespace mb
