// A command-line mistake (unknown option, index out of range): reported with exit code 2.
#pragma once

#include <stdexcept>

namespace twinraster {

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace twinraster
