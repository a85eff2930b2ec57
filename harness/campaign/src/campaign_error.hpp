// The campaign's exception type: what is wrong with a spec, a results table or an output folder, in a
// sentence a user can act on. A failing run is not an error of the campaign: it is recorded in its row.
#pragma once

#include <stdexcept>

namespace campaign {

class CampaignError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace campaign
