// Registers every built-in component in the process-wide registry (idempotent).
#pragma once

namespace sinew {
void register_all_components();
}
