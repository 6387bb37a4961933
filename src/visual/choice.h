// SOFA's selectable-item Data (SelectableItem, OptionsGroup): a text that should be one of a
// fixed list. SOFA reports another text as an error and falls back to the first item, the
// scene still loading (its own OglSceneFrame.scn writes style="1"); so does this check, with a
// warning naming the field, the text and the allowed values.
#pragma once

#include <initializer_list>
#include <string>

#include "core/roles.h"

namespace sinew {

// True when `f`'s text is one of `items`; else warns and sets `f` to the first item.
bool check_choice(const Component& c, Field<std::string>& f, std::initializer_list<const char*> items,
                  Diagnostics& diag);

}  // namespace sinew
