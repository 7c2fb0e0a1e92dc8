#include "common/transport/context.h"

#include <stdexcept>

namespace hexplore::transport {

Context::Context(int io_threads) : context_(io_threads) {
  // No cap on sockets beyond ZeroMQ's default (1023) is needed: a service has a handful.
}

Context::~Context() { guard_.reset(); }

void Context::enable_curve(std::shared_ptr<const CurveKeyring> keyring, CurveGuard::OnRefused on_refused) {
  if (guard_) throw std::logic_error("transport: CURVE is already enabled on this context");
  guard_ = std::make_unique<CurveGuard>(context_, std::move(keyring), std::move(on_refused));
}

}  // namespace hexplore::transport
