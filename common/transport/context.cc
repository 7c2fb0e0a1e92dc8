#include "common/transport/context.h"

namespace hexplore::transport {

Context::Context(int io_threads) : context_(io_threads) {
  // No cap on sockets beyond ZeroMQ's default (1023) is needed: a service has a handful.
}

}  // namespace hexplore::transport
