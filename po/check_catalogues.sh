#!/bin/sh
# The catalogues are complete: every message id of the sources (tr("...") / trf("...")) has a
# translation in po/es.po and an entry in po/en.po, none of them fuzzy, and po/luz.pot is the
# template the sources make today. Also: no source sets a locale, which would change how strtod
# and iostreams read the numbers of scenes and flags.
#   po/check_catalogues.sh SCRATCH_DIR
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
scratch=$1
mkdir -p "$scratch"
sh "$root/po/extract.sh" "$scratch/sources.pot"
status=0
for language in es en; do
  # The sources' ids with the catalogue's translations: an id it lacks comes out untranslated.
  msgmerge --quiet --no-fuzzy-matching --no-wrap "$root/po/$language.po" "$scratch/sources.pot" \
           -o "$scratch/$language.po"
  rm -f "$scratch/$language.missing" "$scratch/$language.fuzzy"  # msgattrib writes nothing when nothing matches
  msgattrib --untranslated --no-obsolete --no-wrap "$scratch/$language.po" -o "$scratch/$language.missing"
  msgattrib --only-fuzzy --no-obsolete --no-wrap "$scratch/$language.po" -o "$scratch/$language.fuzzy"
  for kind in missing fuzzy; do
    if [ -s "$scratch/$language.$kind" ]; then
      echo "po/$language.po: $kind translations of these message ids of the sources:"
      grep -A1 "^msgid" "$scratch/$language.$kind" | grep -v "^msgstr\\|^--"
      status=1
    fi
  done
done
# English left in a Spanish message: the words below, outside what is a name the user types (a
# --flag, a `verb`, a \"quoted\" name, a hyphenated id such as solver-steps or step-01.png, a
# {} placeholder). The CLI's own words (TEXT, FILE, SECONDS) are type names, translated by their ids.
english='the|of|and|with|is|are|from|this|default|jitter|jittered|framing|orthographic|emitter|emitters|SCENE|TEXT|FILE|SECONDS|Press|light|lights|mesh|view|picture|step|steps'
msgattrib --no-wrap --no-obsolete --translated "$scratch/es.po" -o "$scratch/es.translated"
if awk '/^msgstr/ { on = 1; sub(/^msgstr[^ ]* /, "") } /^(msgid|#)/ { on = 0 } on' "$scratch/es.translated" |
   sed -e 's/--[A-Za-z0-9-]*//g' -e 's/`[^`]*`//g' -e 's/\\"[^"]*\\"//g' -e 's/{[^}]*}//g' \
       -e 's/[A-Za-z0-9_.]*-[A-Za-z0-9_.-]*//g' |
   grep -n -w -E "$english" > "$scratch/es.english"; then
  echo "po/es.po: English left in these Spanish messages (words: $english):"
  cat "$scratch/es.english"
  status=1
fi
# The shipped template, but for its creation date.
grep -v '^"POT-Creation-Date:' "$root/po/luz.pot" > "$scratch/shipped.pot"
grep -v '^"POT-Creation-Date:' "$scratch/sources.pot" > "$scratch/fresh.pot"
if ! cmp -s "$scratch/shipped.pot" "$scratch/fresh.pot"; then
  echo "po/luz.pot is not what the sources make: run po/extract.sh po/luz.pot"
  status=1
fi
if grep -rn 'setlocale *( *LC_\|std::locale::global\|\.imbue *(' "$root/src"; then
  echo "the sources above set a locale: numbers must be read in the C locale whatever the environment"
  status=1
fi
exit $status
