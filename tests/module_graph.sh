#!/usr/bin/env bash
# The module graph of the program, from the sources' `use` and `submodule` lines.
#
#   tests/module_graph.sh [--check] [SRC]      (SRC defaults to src)
#
# Prints one line per program unit (module, submodule, program): its floor, its folder, its
# name and the units of SRC it uses.  A unit that uses nothing of SRC is on floor 1; any other
# is one floor above the highest unit it uses (a submodule also above its parent).
#
# The folders under SRC are layers, listed below from the bottom up; the one rule is that a
# unit uses only units of its own folder or of folders below it.  With --check the script
# also fails (exit 1, one line per fault) when a unit uses one of a higher folder, when a
# unit of analyses/ uses another analysis (its own parent module excepted; the modules of
# ANALYSIS_SHARED are not analyses but what every analysis shares: any unit of analyses/
# may use them, and they use no analysis), when a unit
# outside analyses/, app/ and deck/ uses the deck (module deck or any unit of deck/,
# wherever it lies: the layers below take the deck's group types), or when the graph has
# more than MAX_FLOORS floors.
set -u
LAYERS="core linalg integrators model io parallel runs measure deck analyses app"
# The folders that may use the deck.
DECK_USERS="deck analyses app"
# The modules of analyses/ that are not analyses: the base type every analysis extends.
ANALYSIS_SHARED="analysis_base"
MAX_FLOORS=8
check=0
if [ "${1:-}" = "--check" ]; then check=1; shift; fi
src=${1:-src}
[ -d "$src" ] || { echo "module_graph: no folder $src" >&2; exit 2; }

# unit folder kind parent uses... (one line per file)
for f in $(find "$src" -name '*.f90' | sort); do
    folder=$(basename "$(dirname "$f")")
    awk -v folder="$folder" -v file="$f" '
        BEGIN { IGNORECASE = 1 }
        { line = tolower($0); sub(/!.*/, "", line) }
        unit == "" && line ~ /^ *module +[a-z0-9_]+ *$/ { split(line, w, " "); unit = w[2]; kind = "module" }
        unit == "" && line ~ /^ *program +[a-z0-9_]+/ { split(line, w, " "); unit = w[2]; kind = "program" }
        unit == "" && line ~ /^ *submodule *\(/ {
            s = line; sub(/^ *submodule *\( */, "", s); p = s; sub(/ *\).*/, "", p)
            n = s; sub(/^[^)]*\) */, "", n); sub(/ .*/, "", n); unit = n; kind = "submodule"; parent = p }
        line ~ /^ *use +[a-z0-9_]+/ { s = line; sub(/^ *use +/, "", s); sub(/[ ,].*/, "", s); uses[s] = 1 }
        END {
            if (unit == "") exit
            if (kind == "module" && file ~ /_mpi\.f90$/) kind = "module(mpi)"
            printf "%s %s %s %s", unit, folder, kind, (parent == "" ? "-" : parent)
            for (u in uses) printf " %s", u
            printf "\n"
        }' "$f"
done | awk -v layers="$LAYERS" -v check="$check" -v maxf="$MAX_FLOORS" -v deckusers="$DECK_USERS" \
          -v shared="$ANALYSIS_SHARED" '
    BEGIN { n = split(layers, L, " "); for (i = 1; i <= n; i++) rank[L[i]] = i
            n = split(deckusers, D, " "); for (i = 1; i <= n; i++) may_use_deck[D[i]] = 1
            n = split(shared, S, " "); for (i = 1; i <= n; i++) is_shared[S[i]] = 1 }
    {
        u = $1; if (u in folder && $3 == "module(mpi)") next    # the MPI twin of a module
        folder[u] = $2; kind[u] = $3; parent[u] = $4; nu[u] = 0
        for (i = 5; i <= NF; i++) use[u, ++nu[u]] = $i
        order[++nunits] = u
    }
    function floor_of(u,    i, f, g) {
        if (u in fl) return fl[u]
        fl[u] = 1                                   # cycles cannot occur in Fortran
        f = 0
        if (parent[u] != "-" && parent[u] in folder) f = floor_of(parent[u])
        for (i = 1; i <= nu[u]; i++) if (use[u, i] in folder) { g = floor_of(use[u, i]); if (g > f) f = g }
        fl[u] = f + 1
        return fl[u]
    }
    END {
        bad = 0; top = 0
        for (k = 1; k <= nunits; k++) {
            u = order[k]; f = floor_of(u); if (f > top) top = f
            deps = ""
            for (i = 1; i <= nu[u]; i++) if (use[u, i] in folder) deps = deps " " use[u, i]
            line[k] = sprintf("%2d %-12s %-10s %s%s:%s", f, folder[u], kind[u], u, \
                (parent[u] == "-" ? "" : " (of " parent[u] ")"), deps)
            if (!(folder[u] in rank)) { fault[++bad] = u ": folder " folder[u] " is not a layer" ; continue }
            for (i = 1; i <= nu[u]; i++) {
                v = use[u, i]; if (!(v in folder)) continue
                if (rank[folder[v]] > rank[folder[u]])
                    fault[++bad] = u " (" folder[u] ") uses " v " of the higher folder " folder[v]
                else if (folder[u] == "analyses" && folder[v] == "analyses" && v != parent[u] && \
                         parent[v] != u && !(v in is_shared))
                    fault[++bad] = u " uses " v ": an analysis uses another analysis"
                if ((v == "deck" || folder[v] == "deck") && !(folder[u] in may_use_deck))
                    fault[++bad] = u " (" folder[u] ") uses " v ": only analyses/ and app/ use the deck"
            }
        }
        # print sorted by floor, then name
        for (f = 1; f <= top; f++) for (k = 1; k <= nunits; k++) if (fl[order[k]] == f) print line[k]
        print top " floors, " nunits " units"
        if (check) {
            if (top > maxf) fault[++bad] = "the graph has " top " floors; allowed: at most " maxf
            for (i = 1; i <= bad; i++) print "module_graph: " fault[i] > "/dev/stderr"
            exit (bad > 0)
        }
    }'
