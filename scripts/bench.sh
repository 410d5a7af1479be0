#!/usr/bin/env bash
# Runs the benchmarks (or takes their output from a directory), keeps each one's final JSON
# object in bench/results/NAME.json with the date and the machine added, and rewrites the
# tables of bench/README.md and bench/GEOMETRY.md (between <!-- bench:NAME --> and
# <!-- /bench:NAME -->) from them.
#
#   scripts/bench.sh [--build DIR] [--from DIR] [--tables-only] [NAME...]
#
# NAME: geom_kernel knot_removal curvemap render store pick blade acsynt_loft exchange demo
# (default: all).
# --build DIR    where the bench_* programs are (default build/bench; build them first with
#                cmake --build build --target bench_NAME).
# --from DIR     do not run: take DIR/NAME.json, or the last line of DIR/NAME.log or
#                DIR/bench_NAME.log that is a JSON object (a run's saved output).
# --tables-only  run nothing: rewrite the README's tables from bench/results/*.json.
# Only awk and coreutils are needed. Fails when a program's output does not end with one
# JSON object.
set -euo pipefail
cd "$(dirname "$0")/.."

all=(geom_kernel knot_removal curvemap render store pick blade acsynt_loft exchange demo)
build=build/bench from="" tables_only=0 names=()
while (($#)); do
  case $1 in
    --build) build=$2; shift 2 ;;
    --from) from=$2; shift 2 ;;
    --tables-only) tables_only=1; shift ;;
    -h|--help) sed -n '2,15p' "$0"; exit 0 ;;
    -*) echo "bench.sh: unknown option $1" >&2; exit 2 ;;
    *) names+=("$1"); shift ;;
  esac
done
((${#names[@]})) || names=("${all[@]}")
results=bench/results
mkdir -p "$results"

# The machine in words, without commas (it goes into a JSON string).
machine() {
  local cpu cores
  cpu=$(awk -F': ' '/^model name/ {print $2; exit}' /proc/cpuinfo 2>/dev/null || true)
  cores=$(nproc 2>/dev/null || echo "?")
  echo "${cpu:-unknown CPU} (${cores} cores) $(uname -sr)" | tr -d ',"'
}

# The last line of a file that is one JSON object; fails naming the file otherwise.
last_object() {
  local line
  line=$(grep -E '^[[:space:]]*\{.*\}[[:space:]]*$' "$1" | tail -n 1 || true)
  if [ -z "$line" ]; then
    echo "bench.sh: $1 does not end with a JSON object" >&2
    return 1
  fi
  local last
  last=$(grep -v '^[[:space:]]*$' "$1" | tail -n 1)
  if [ "$last" != "$line" ]; then
    echo "bench.sh: $1: the JSON object is not the last line" >&2
    return 1
  fi
  echo "$line"
}

# Adds "date", "machine" and the load average at the start in front of an object that lacks them.
stamp() {
  local object=$1
  if [[ $object == *'"date"'* ]]; then
    echo "$object"
  else
    local load
    load=$(cut -d' ' -f1 /proc/loadavg 2>/dev/null || echo "?")
    echo "{\"date\": \"$(date -u +%Y-%m-%d)\", \"machine\": \"$(machine)\", \"load_average\": \"$load\", ${object#\{}"
  fi
}

if ((!tables_only)); then
  for name in "${names[@]}"; do
    if [ -n "$from" ]; then
      source=""
      for candidate in "$from/$name.json" "$from/$name.log" "$from/bench_$name.log"; do
        if [ -f "$candidate" ]; then source=$candidate; break; fi
      done
      [ -n "$source" ] || { echo "bench.sh: no $name.json or $name.log in $from" >&2; exit 1; }
    else
      program=$build/bench_$name
      [ -x "$program" ] || { echo "bench.sh: $program is not built (cmake --build build --target bench_$name)" >&2; exit 1; }
      source=$(mktemp)
      echo "bench.sh: running $program" >&2
      # From the program's folder: some find their data relative to their source file.
      (cd "$(dirname "$program")" && "./$(basename "$program")") >"$source"
    fi
    object=$(last_object "$source")
    stamp "$object" >"$results/$name.json"
    echo "bench.sh: $results/$name.json" >&2
  done
fi

# Table layouts: rows (key prefixes; "-" = none) | columns (key suffixes, key=Label with _ for
# blanks) | run-wide figures named in the date line.
layout() {
  case $1 in
    geom_kernel) echo "poly rational degree1 deg2x5_double_knots wide_weights periodic_tube|grid_fast_ns_per_point=fast_grid_ns grid_plain_ns_per_point=plain_ns sisl_s1421_ns_per_point=SISL_s1421_ns plain_vs_s1421=plain/s1421 intersect_us_per_query=intersect_µs sisl_s1856_us_per_query=SISL_s1856_µs intersect_speedup_vs_s1856=speed-up closest_us_per_query=closest_µs sisl_s1958_us_per_query=SISL_s1958_µs closest_speedup_vs_s1958=speed-up closest_farther_than_foot=farther_than_foot sisl_closest_farther_than_foot=SISL_farther|wall_seconds cpu_seconds" ;;
    knot_removal) echo "ibeam_tol1.0e-02 ibeam_tol1.2e-03 ibeam_tol1.0e-03 ibeam_tol1.0e-04 airfoil_tol1.0e-02 airfoil_tol1.2e-03 airfoil_tol1.0e-03 airfoil_tol1.0e-04 degree1 degree2 degree3 degree4 degree5 degree6 degree7 c0_corners noisy_digitised incompressible long_2500 rational|geom_control_points=geom_CPs geom_max_error=geom_error geom_error_over_tolerance=geom_error_/_tolerance geom_ms sisl_control_points=SISL_CPs sisl_max_error=SISL_error sisl_ms=SISL_ms geom_loop_control_points=loop_CPs geom_loop_max_error=loop_error geom_loop_ms=loop_ms members_worst_time_ratio=8_members_worst_time members_worst_cp_ratio=8_members_worst_CPs|wall_seconds cpu_seconds worst_time_ratio_vs_sisl worst_cp_ratio_vs_sisl worst_error_over_tolerance members_worst_time_ratio_vs_sisl members_worst_cp_ratio_vs_sisl members_worst_error_over_tolerance" ;;
    curvemap) echo "wave wing|tolerance_model_units=tolerance adaptive_ms adaptive_projections adaptive_max_deviation seed10_ms=10_per_segment_ms seed10_max_deviation=10_per_segment_deviation fixed_equal_per_segment=equal_deviation_per_segment fixed_equal_ms=equal_deviation_ms fixed_equal_projections=equal_deviation_projections|" ;;
    render) echo "-|triangles iso_line_segments store_frame_cpu_ms raw_frame_cpu_ms store_frame_over_raw_cpu=ratio_CPU store_frame_over_raw=ratio_wall unchanged_frame_uploaded_bytes=unchanged_bytes edit_uploaded_bytes edit_structure_buffer_bytes=structure_bytes edit_uploads_only_that_structure=only_that_structure|width_px height_px" ;;
    store) echo "e10k e100k e1M e4M|elements inserts_per_s traversal_ns_per_element=traversal_ns raw_visit_ns_per_element=plain_vectors_ns incremental_unchanged_ns_per_element=unchanged_ns peak_rss_bytes_per_element=peak_RSS_B resident_after_insert_bytes_per_element=store_RSS_B traversal_over_raw=traversal_/_plain edit_to_drawlist_ms=edit_to_draw_list_ms edit_retraversed_elements=edit_retraversed edit_retessellated_surfaces=edit_retessellated first_traversal_cpu_s=first_traversal_s|traversal_growth_10k_to_4M raw_visit_growth_10k_to_4M traversal_growth_1M_to_4M raw_visit_growth_1M_to_4M" ;;
    demo) echo "-|demo_cpu_s demo_peak_rss_mb demo_wall_s startup_cpu_s startup_peak_rss_mb demo_without_pdf_cpu_s=without_PDF_cpu_s demo_without_pdf_peak_rss_mb=without_PDF_rss_mb demo_cold_shader_cache_cpu_s=first_run_cpu_s|runs" ;;
    pick) echo "aircraft_1k aircraft_10k tubes|patches picks hits same_hit median_us=median_µs_CPU p99_us=p99_µs_CPU hit_median_us=hits_median_µs wall_median_us=median_µs_wall brute_median_us=every_item_median_µs brute_p99_us=every_item_p99_µs tree_build_ms|same_hit_as_brute_force session_pick_ms session_traversal_ms session_10k_pick_ms session_10k_traversal_ms cpu_seconds wall_seconds" ;;
    blade) echo "-|blade_points blade_ms recursion_ms thesis_program_ms thesis_seconds largest_difference|cpu_seconds wall_seconds" ;;
    acsynt_loft) echo "transport fighter|load_loft_ms=load_and_loft_ms patches|" ;;
    exchange) echo "split1 split2 split3 split4 split6 split7|patches iges_cpu_s=IGES_cpu_s iges_wall_s=IGES_wall_s iges_us_per_patch=IGES_µs_a_patch step_cpu_s=STEP_cpu_s step_us_per_patch=STEP_µs_a_patch stock_iges_cpu_s=OpenCASCADE_IGES_cpu_s stock_over_iges=OpenCASCADE_/_ours|iges_per_patch_growth step_per_patch_growth cpu_seconds wall_seconds" ;;
    *) echo "bench.sh: no table layout for $1" >&2; return 1 ;;
  esac
}

# One dated markdown table from a results file and a layout.
table() {
  awk -v spec="$2" '
    function label(s) { gsub(/_/, " ", s); return s }
    # Reals to three significant digits (whole numbers from 100 up); integers and text as they are.
    function shown(x) {
      if (x ~ /^-?[0-9]+$/ || x !~ /^-?[0-9.]+([eE][-+]?[0-9]+)?$/) return x
      return (x + 0 >= 100 || x + 0 <= -100) ? sprintf("%.0f", x) : sprintf("%.3g", x)
    }
    {
      text = text $0
    }
    END {
      while (match(text, /"[^"]+": *("[^"]*"|[^,}]+)/)) {
        pair = substr(text, RSTART, RLENGTH); text = substr(text, RSTART + RLENGTH)
        key = substr(pair, 2); sub(/".*/, "", key)
        value = pair; sub(/^"[^"]+": */, "", value); gsub(/^"|"$/, "", value); gsub(/ +$/, "", value)
        v[key] = value
      }
      split(spec, part, "|"); nr = split(part[1], rows, " "); nc = split(part[2], cols, " ")
      nw = split(part[3], wide, " ")
      line = "Run of " v["date"] " on " v["machine"]
      for (i = 1; i <= nw; i++) if (wide[i] in v) line = line ", " label(wide[i]) " " v[wide[i]]
      if ("load_average" in v) line = line ", load average " v["load_average"]
      if ("note" in v) line = line " (" v["note"] ")"
      print line "."
      print ""
      header = "|"; rule = "|"
      if (!(nr == 1 && rows[1] == "-")) { header = header " |"; rule = rule "---|" }
      for (c = 1; c <= nc; c++) {
        name = cols[c]; text = name
        if (index(name, "=")) { text = substr(name, index(name, "=") + 1); cols[c] = substr(name, 1, index(name, "=") - 1) }
        header = header " " label(text) " |"; rule = rule "---|"
      }
      print header; print rule
      for (r = 1; r <= nr; r++) {
        prefix = rows[r] == "-" ? "" : rows[r] "_"; out = "|"; any = 0
        if (rows[r] != "-") out = out " " label(rows[r]) " |"
        for (c = 1; c <= nc; c++) {
          k = prefix cols[c]
          if (k in v) { out = out " " shown(v[k]) " |"; any = 1 } else out = out " - |"
        }
        if (any) print out
      }
    }' "$1"
}

# Rewrites each marked block, in whichever of the tables' files holds it, whose results file exists.
files=(bench/README.md bench/GEOMETRY.md)
for name in "${all[@]}"; do
  file=$results/$name.json
  [ -f "$file" ] || continue
  readme=""
  for candidate in "${files[@]}"; do
    if grep -q "<!-- bench:$name -->" "$candidate"; then readme=$candidate; break; fi
  done
  [ -n "$readme" ] || { echo "bench.sh: no <!-- bench:$name --> block in ${files[*]}" >&2; exit 1; }
  block=$(mktemp)
  table "$file" "$(layout "$name")" >"$block"
  awk -v name="$name" -v block="$block" '
    $0 == "<!-- bench:" name " -->" { print; while ((getline line < block) > 0) print line; skip = 1; next }
    $0 == "<!-- /bench:" name " -->" { skip = 0 }
    !skip' "$readme" >"$readme.tmp"
  mv "$readme.tmp" "$readme"
  rm -f "$block"
done
echo "bench.sh: tables of ${files[*]} rewritten" >&2
