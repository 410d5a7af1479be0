#!/usr/bin/env bash
# The acsynt program's exit status, its last line and its refusals of paths and options, run as
# a user runs it: test_acsynt_program.sh ACSYNT_BINARY WORK_DIR EXCHANGE_MODULE MODULE_DIR (the
# module's folder relative to the program's in an install). Each check prints what failed.
set -u
acsynt=$(realpath "$1")
work=$2
module=$(realpath "$3")
install_dir=$4
rm -rf "$work" && mkdir -p "$work"
cd "$work" || exit 1
failures=0
fail() { echo "FAILED: $*"; failures=$((failures + 1)); }

# run NAME EXPECTED_STATUS ARGS...: runs the program, keeping stdout and stderr in NAME.out/.err.
run() {
  local name=$1 expected=$2
  shift 2
  "$acsynt" "$@" >"$name.out" 2>"$name.err"
  local status=$?
  [ "$status" -eq "$expected" ] || fail "$name: exit status $status, expected $expected ($(cat "$name.err"))"
}
# expect_in FILE TEXT: FILE contains TEXT.
expect_in() { grep -qF -- "$2" "$1" || fail "$1 does not say '$2': $(tail -3 "$1")"; }
last_line_is() { [ "$(tail -n 1 "$1")" = "$2" ] || fail "$1 ends with '$(tail -n 1 "$1")', not '$2'"; }

printf 'choice FILE\nchoice READ_MODEL\nstring fighter.acm\nchoice RETURN\nsummary good\n' >good.session
run good 0 --script good.session --output out_good --size 320x240
[ -f out_good/good.txt ] || fail "good: the summary directive wrote nothing"
grep -q "errors\? in" good.out && fail "good: a clean run reports errors"

# Every file the session wrote is printed, the FILE menu's too, each once (a `summary summary`
# and the run's own summary.txt too); a directive's name that already has its extension keeps it.
printf 'choice FILE\nchoice READ_MODEL\nstring fighter.acm\nchoice SAVE_MODEL\nstring saved.acs\nchoice ARCHIVE\nstring saved.phg\nchoice SAVE_MODEL\nstring saved.acs\nchoice RETURN\nsnapshot shot.png\nsummary listed.txt\nsummary summary\n' >saved.session
run saved 0 --script saved.session --output out_saved --size 320x240
for file in out_saved/saved.acs out_saved/saved.phg out_saved/shot.png out_saved/listed.txt out_saved/summary.txt; do
  [ -f "$file" ] || fail "saved: $file was not written"
  [ "$(grep -cxF "$file" saved.out)" -eq 1 ] || fail "saved: $file is not printed once: $(cat saved.out)"
done

# A failing line stops the run (exit 3, the count last); --keep-going carries on and counts all.
printf 'choice FILE\nchoice NO_SUCH_ITEM\nstring missing.acm\nchoice RETURN\nsummary after\n' >bad.session
run stop 3 --script bad.session --output out_stop --size 320x240
last_line_is stop.out "1 error in bad.session"
[ -f out_stop/after.txt ] && fail "stop: lines after the first failure ran"
expect_in out_stop/acsynt.log "ERROR:"
run keepgoing 3 --script bad.session --keep-going --output out_keep --size 320x240
last_line_is keepgoing.out "2 errors in bad.session"
[ -f out_keep/after.txt ] || fail "keep-going: the run stopped early"
# Directives stop the run too: a failing view does not let the summary after it run.
printf 'choice FILE\nchoice READ_MODEL\nstring fighter.acm\nchoice RETURN\nview 0 30 0.1\nsummary after\n' >badview.session
run badview 3 --script badview.session --output out_badview --size 320x240
last_line_is badview.out "1 error in badview.session"
[ -f out_badview/after.txt ] && fail "badview: the summary after a failing view ran"
run badview_keep 3 --script badview.session --keep-going --output out_badview_keep --size 320x240
[ -f out_badview_keep/after.txt ] || fail "badview keep-going: the run stopped early"

# A script that ends with a prompt open (READ MODEL's file name never given) left its command undone.
printf 'choice FILE\nchoice READ_MODEL\n' >open.session
run openprompt 3 --script open.session --output out_open --size 320x240
last_line_is openprompt.out "1 error in open.session"
expect_in out_open/acsynt.log "THE SCRIPT ENDED AT THE PROMPT"

# Stopped by SIGTERM (as `timeout` stops it) in a long run: the session ends after its line, the
# summary and log are written with the lines done so far, the status is 128 + 15.
{
  printf 'choice FILE\nchoice READ_MODEL\nstring fighter.acm\nchoice RETURN\n'
  for i in $(seq 1 3000); do printf 'snapshot long_%s\n' "$i"; done
  printf 'summary after\n'
} >long.session
"$acsynt" --script long.session --output out_long --size 320x240 >long.out 2>long.err &
pid=$!
for _ in $(seq 1 600); do [ -f out_long/long_3.png ] && break; sleep 0.1; done
[ -f out_long/long_3.png ] || fail "long: no third picture within 60 s"
kill -TERM "$pid"
wait "$pid"
status=$?
[ "$status" -eq 143 ] || fail "long: exit status $status after SIGTERM, expected 143 ($(tail -2 long.err))"
[ -f out_long/summary.txt ] || fail "long: no summary after SIGTERM"
expect_in out_long/acsynt.log "MODEL fighter READ"
expect_in long.out "stopped by signal 15"
[ -f out_long/after.txt ] && fail "long: the run went on to its end after SIGTERM"

# Lines no menu or device takes are errors too, each naming its line in the log.
printf 'choice 0\nchoice FILE device 7\nstring hello\nchoice FILE\n' >ignored.session
run ignored 3 --script ignored.session --keep-going --output out_ignored --size 320x240
last_line_is ignored.out "3 errors in ignored.session"
expect_in out_ignored/acsynt.log "ERROR: NO MENU ITEM CHOSEN (CHOICE 0): THE ITEMS ARE 1..8 (ignored.session line 1)"
expect_in out_ignored/acsynt.log "ignored.session line 2: 'choice FILE device 7' reached no device"
expect_in out_ignored/acsynt.log "ERROR: NO TEXT EXPECTED: 'hello' (ignored.session line 3)"

# Files a script names stay inside --output.
printf 'summary ../escaped\nsummary /tmp/acsynt_escaped_%s\nsummary inside\n' "$$" >escape.session
run escape 3 --script escape.session --keep-going --output out_escape --size 320x240
[ -e escaped.txt ] && fail "escape: a summary was written outside --output"
[ -e "/tmp/acsynt_escaped_$$.txt" ] && fail "escape: an absolute summary path was written"
[ -f out_escape/inside.txt ] || fail "escape: the plain summary was not written"
last_line_is escape.out "2 errors in escape.session"

# A directory where a model is expected is named as such.
mkdir -p somedir
printf 'choice FILE\nchoice READ_MODEL\nstring somedir\n' >dirmodel.session
run dirmodel 3 --script dirmodel.session --output out_dir --size 320x240
expect_in out_dir/acsynt.log "is a directory"

# Paths and options refused before anything runs (status 2, the reason on stderr).
run record_dir 2 --script good.session --record somedir --output out_r1 --size 320x240
expect_in record_dir.err "--record somedir is a directory"
run record_missing 2 --script good.session --record no/such/folder/x.session --output out_r2
expect_in record_missing.err "folder that does not exist"
# A file that does not open for writing, where permissions alone say yes (root under /proc).
if [ -d /proc/self ]; then
  run record_proc 2 --script good.session --record /proc/acsynt_no.session --output out_r3 --size 320x240
  expect_in record_proc.err "--record /proc/acsynt_no.session cannot be written"
  [ -d out_r3 ] && [ -n "$(ls out_r3)" ] && fail "record_proc: the session ran"
fi
# A recording that would overwrite the script it replays, or the summary and log the session
# writes at its end, is refused (the script was replaced, the log lost).
cp good.session mine.session
run record_script 2 --script mine.session --record ./mine.session --output out_r4 --size 320x240
expect_in record_script.err "--record ./mine.session is the script it would replace"
cmp -s good.session mine.session || fail "record_script: the script was changed"
mkdir -p out_r5
for written in acsynt.log summary.txt; do
  run "record_$written" 2 --script good.session --record "out_r5/$written" --output out_r5 --size 320x240
  expect_in "record_$written.err" "is the $written the session writes into --output"
done
run script_dir 2 --script somedir --output out_s
expect_in script_dir.err "--script somedir is a directory"
run script_missing 2 --script nothing.session --output out_m
expect_in script_missing.err "cannot be read"
# A device or a pipe where a file is expected is refused, not read for ever.
run script_device 2 --script /dev/zero --output out_z
expect_in script_device.err "--script /dev/zero is not a regular file"
run import_device 2 --import /dev/zero --script good.session --output out_zi
expect_in import_device.err "--import /dev/zero is not a regular file"
printf 'choice FILE\nchoice READ_MODEL\nstring /dev/zero\n' >devmodel.session
run devmodel 3 --script devmodel.session --output out_dev --size 320x240
expect_in out_dev/acsynt.log "/dev/zero:0: is not a regular file"
touch plainfile
run output_file 2 --script good.session --output plainfile
expect_in output_file.err "is not a directory"
run size_junk 2 --script good.session --size 1024x768junk
expect_in size_junk.err "--size wants WxH"
run size_sign 2 --script good.session --size +320x240
run size_shape 2 --script good.session --size 1024x700
expect_in size_shape.err "a script's screen is 4:3"
run extra_argument 2 --script good.session extra
expect_in extra_argument.err "unexpected argument 'extra'"
run both_modes 2 --script good.session --window

# A script with a NUL byte is refused whole, naming the byte (the message is not cut at it).
printf 'choice FILE\nstring ab\0cd\n' >nul.session
run nul 1 --script nul.session --output out_nul
expect_in nul.err "nul.session:2: control character 0x00 at column 10"

# --export converts a model to STEP or IGES without a session; --import reads one as the first model.
run export_step 0 --export transport.step transport.acm
[ -s transport.step ] || fail "export_step: no transport.step"
run export_iges 0 --export fighter.igs fighter.acm
[ -s fighter.igs ] || fail "export_iges: no fighter.igs"
# A recording may not overwrite the CAD file the session imports.
cp fighter.igs mine.igs
run record_import 2 --import mine.igs --script good.session --record mine.igs --output out_r6 --size 320x240
expect_in record_import.err "--record mine.igs is the --import file"
cmp -s fighter.igs mine.igs || fail "record_import: the CAD file was changed"
# A name a script line cannot hold (a control character) is noted in the recording, not written
# as a line that would import another file.
newline_dir=$(printf 'd\n1')
mkdir -p "$newline_dir" && cp fighter.igs "$newline_dir/fighter.igs"
run record_newline 0 --import "$newline_dir/fighter.igs" --script good.session --record newline.session \
  --output out_r7 --size 320x240
expect_in newline.session "# began with --import of a file a script line cannot name"
grep -q "choice IMPORT" newline.session && fail "record_newline: an IMPORT line for a name with a newline"
run export_ext 2 --export transport.dxf transport.acm
expect_in export_ext.err "unknown extension '.dxf'"
run export_missing 2 --export t.step nothing.acm
expect_in export_missing.err "nothing.acm cannot be read"
mkdir -p dir.step
run export_dir 2 --export dir.step transport.acm
expect_in export_dir.err "is a directory"
printf 'acsynt-model 1\nmodel broken\n' >broken.acm
run export_broken 1 --export broken.step broken.acm
expect_in export_broken.err "broken.acm:"
run export_and_script 2 --export t.step transport.acm --script good.session
# A saved model exports as a description does; a CAD file as MODEL is the other way round.
run export_saved 0 --export saved_model.igs out_saved/saved.acs
[ -s saved_model.igs ] || fail "export_saved: no saved_model.igs"
run export_cad_model 2 --export t.step transport.step
expect_in export_cad_model.err "transport.step is an IGES or STEP file"
printf 'choice MODELS\nchoice LIST\nsummary imported\n' >list.session
run import_step 0 --import transport.step --script list.session --output out_import --size 320x240
expect_in out_import/imported.txt "model transport (current): 8 components, 376 patches"
run import_iges 0 --import fighter.igs --script list.session --output out_import_iges --size 320x240 \
  --record import.session
expect_in out_import_iges/imported.txt "model fighter (current): 6 components, 192 patches"
# The recording holds the import: it replays without --import to the same summary.
expect_in import.session "choice IMPORT"
run import_replay 0 --script import.session --output out_import_replay --size 640x480
cmp -s out_import_iges/imported.txt out_import_replay/imported.txt ||
  fail "import_replay: $(diff out_import_iges/imported.txt out_import_replay/imported.txt)"
# A string line holds '#' (a comment starts anywhere else): a path with one records and replays.
mkdir -p 'd#1' && cp fighter.igs 'd#1/fighter.igs'
run record_hash 0 --import 'd#1/fighter.igs' --script list.session --output out_hash --size 320x240 \
  --record hash.session
expect_in hash.session "d#1/fighter.igs"
run replay_hash 0 --script hash.session --output out_hash_replay --size 640x480
cmp -s out_hash/imported.txt out_hash_replay/imported.txt ||
  fail "replay_hash: $(diff out_hash/imported.txt out_hash_replay/imported.txt)"
run import_missing 2 --import nothing.step --script list.session --output out_import_missing
run import_ext 2 --import transport.acm --script list.session --output out_import_ext
expect_in import_ext.err "--import unknown extension '.acm'"
run import_saved 0 --import saved_model.igs --script list.session --output out_import_saved --size 320x240
expect_in out_import_saved/imported.txt "model fighter (current): 6 components, 192 patches"
expect_in import_missing.err "--import nothing.step cannot be read"
head -c 20000 transport.step >cut.step
run import_cut 1 --import cut.step --script list.session --output out_import_cut --size 320x240
expect_in import_cut.err "cut.step: not a readable STEP file"

# The exchange module is found next to the program, then in the installed layout, so the
# program can move with it: a copy that is not a module, in either place, is the one refused.
mkdir -p moved installed/bin "installed/bin/$install_dir"
cp "$acsynt" moved/acsynt && cp "$module" moved/
cp "$acsynt" installed/bin/acsynt && cp "$module" "installed/bin/$install_dir/"
acsynt_built=$acsynt
for place in moved installed/bin; do
  acsynt=$(realpath "$place/acsynt")
  run "export_$(basename "$place")" 0 --export "$place.step" transport.acm
  [ -s "$place.step" ] || fail "export from $place: no $place.step"
done
echo "not a module" >"installed/bin/$install_dir/$(basename "$module")"
run export_installed_broken 2 --export broken_installed.step transport.acm
expect_in export_installed_broken.err "$(realpath -m "installed/bin/$install_dir/$(basename "$module")")"
echo "not a module" >"moved/$(basename "$module")"
acsynt=$(realpath moved/acsynt)
run export_moved_broken 2 --export broken_moved.step transport.acm
expect_in export_moved_broken.err "$(realpath moved)/$(basename "$module") cannot be loaded"
acsynt=$acsynt_built

# --help names the window's buttons and keys.
run help 0 --help
expect_in help.out "Enter accepts it"
expect_in help.out "Escape withdraws it"
expect_in help.out "drags a slider"
expect_in help.out "left drag in a view: rotate"
expect_in help.out "wheel in a view: zoom"
expect_in help.out "F1 or H"
expect_in help.out "Ctrl+Z / Ctrl+Y"

if [ "$failures" -ne 0 ]; then
  echo "$failures checks failed"
  exit 1
fi
echo "all program checks passed"
