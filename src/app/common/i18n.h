#pragma once
// The app's code writes tr("..."), trf("..."), trn / trnf (plural forms) and N_("..."), the
// keywords xgettext is given; the
// catalogues and the language live in core/i18n.h, where the loader's messages reach them too.
#include "core/i18n.h"

namespace luz::app {
using i18n::tr;
using i18n::trf;
using i18n::trn;
using i18n::trnf;
using i18n::N_;
}  // namespace luz::app
