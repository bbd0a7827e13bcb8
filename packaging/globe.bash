# Bash completion for globe and globe-tiler: subcommands, then the options the program's own
# --help lists for that subcommand, then files. Both lists come from --help (globe's "Subcommands:"
# table, globe-tiler's "globe-tiler NAME ..." lines), so they cannot fall out of step.
# Installed to share/bash-completion/completions/ (for both names); or: source this file.

_globe_complete() {
  local program=$1 current=${COMP_WORDS[COMP_CWORD]}
  local subcommands="" subcommand="" word
  case "${program##*/}" in
    globe) subcommands=$("$program" --help 2>/dev/null |
      sed -nE '/^Subcommands:/,$ s/^  ([a-z][a-z-]*) .*/\1/p' | tr '\n' ' ') ;;
    globe-tiler) subcommands=$("$program" --help 2>/dev/null |
      sed -nE 's/^(Also:)? +globe-tiler ([a-z][a-z-]*) .*/\2/p' | sort -u | tr '\n' ' ') ;;
  esac
  for word in "${COMP_WORDS[@]:1:COMP_CWORD-1}"; do
    case " $subcommands " in *" $word "*) subcommand=$word; break ;; esac
  done
  if [[ $current == -* ]]; then
    local options
    # CLI11's option lines: "  -o,--output TEXT ...": the first field, split at commas (a
    # letter after the dashes, so a "  - rule" line of the help's footer is no option).
    options=$("$program" ${subcommand:+"$subcommand"} --help 2>/dev/null |
      sed -nE 's/^ +(--?[A-Za-z][^ ]*).*/\1/p' | tr ',' '\n' | sort -u)
    mapfile -t COMPREPLY < <(compgen -W "$options" -- "$current")
  elif [[ -z $subcommand && -n $subcommands && $COMP_CWORD -eq 1 ]]; then
    mapfile -t COMPREPLY < <(compgen -W "$subcommands" -- "$current")
  else
    mapfile -t COMPREPLY < <(compgen -f -- "$current")
  fi
}
complete -o filenames -F _globe_complete globe globe-tiler
