// PCCD/Continuous/Contact_time_names.h -- the names under which the tools and the Python module
// report a Contact_time_result (`pccd contact-time --json`, pccd.ContactTimeResult): the status's
// name and the counters' names, one list for both (doc/manual/continuous.md, "CLI and Python").
#pragma once

#include <concepts>
#include <optional>
#include <string_view>
#include <type_traits>

#include <PCCD/Continuous/Contact_time_options.h>

namespace PCCD {

/// "contact", "no_contact" or "undecided": the enumerator's name.
inline const char* to_string(Contact_time_status status)
{
    switch (status) {
    case Contact_time_status::contact: return "contact";
    case Contact_time_status::no_contact: return "no_contact";
    case Contact_time_status::undecided: return "undecided";
    }
    return "unknown";
}

/// The status named `name` (one of to_string's), if it is one.
inline std::optional<Contact_time_status> contact_time_status_from_string(std::string_view name)
{
    for (const Contact_time_status s :
         {Contact_time_status::contact, Contact_time_status::no_contact, Contact_time_status::undecided})
        if (name == to_string(s)) return s;
    return std::nullopt;
}

/// Calls `f(name, value)` for every counter of `counters`, in a fixed order, with the field's name.
template <class Counters, class F>
    requires std::same_as<std::remove_cvref_t<Counters>, Contact_time_counters>
void for_each_counter(Counters&& counters, F&& f)
{
    f("advancement_steps", counters.advancement_steps);
    f("near_checks", counters.near_checks);
    f("bisection_steps", counters.bisection_steps);
    f("node_pairs", counters.node_pairs);
    f("f_evaluations", counters.f_evaluations);
}

} // namespace PCCD
