// A failure one rank meets, made every rank's (docs/parallel.md 5): the ranks that did not
// meet it would otherwise wait for the one that did in their next collective.
//   agreeOnFailure<Thrown, Caught>(work): runs work(); if it threw a Caught on any rank,
//   every rank throws Thrown with the message of the lowest rank that failed. In a serial
//   run work() runs alone and its exception passes unchanged. Collective.
// Reads no dictionary keys.
#pragma once
#include "parallel/Communicator.hpp"
#include <exception>
#include <string>

namespace shizuku {

template <class Thrown, class Caught = std::exception, class F>
void agreeOnFailure(F&& work) {
  const auto& world = Communicator::world();
  if (!world.isParallel()) {
    work();
    return;
  }
  std::string failure;
  try {
    work();
  } catch (const Caught& e) {
    failure = e.what();
    if (failure.empty()) failure = "failed";
  }
  failure = world.firstMessage(failure);
  if (!failure.empty()) throw Thrown(failure);
}

}  // namespace shizuku
