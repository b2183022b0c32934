#pragma once
/// @file
/// Text that is safe to show on a terminal.

#include <string>
#include <string_view>

namespace feran {

/// @p text with everything a terminal would act on made visible: the C0 control
/// characters and DEL as `\n`, `\r`, `\t`, `\e` or `\xNN`, and the C1 controls
/// (U+0080–U+009F in UTF-8, which some terminals also obey) as `\u00NN`. Names from a
/// model file or the command line go through it before they are printed, so that a
/// name cannot move the cursor, change colours or break a table's lines. With
/// @p keep_newlines line feeds stay (for messages of several lines).
std::string printable(std::string_view text, bool keep_newlines = false);

}  // namespace feran
