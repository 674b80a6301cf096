#!/bin/sh
# Writes the message ids of the sources (every tr("..."), trf("..."), trn / trnf's two forms and N_("...")) as a gettext template to $1:
#   po/extract.sh po/luz.pot     refresh the template that ships
# then merge it into the catalogues: msgmerge --update --no-location po/es.po po/luz.pot
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
find src -name '*.cpp' -o -name '*.h' | LC_ALL=C sort |
  xgettext --files-from=- --language=C++ --from-code=UTF-8 --keyword=tr --keyword=trf --keyword=trn:1,2 --keyword=trnf:1,2 --keyword=N_ --add-comments=TRANSLATORS \
           --package-name=luz --no-location --sort-output --output="$1"
