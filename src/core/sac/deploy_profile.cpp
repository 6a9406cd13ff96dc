#include "core/sac/deploy_profile.h"

namespace autoblock {

DeployProfile& deploy_profile() {
  thread_local DeployProfile profile;
  return profile;
}

}  // namespace autoblock
