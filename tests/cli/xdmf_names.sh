#!/usr/bin/env bash
# A ':' cannot stand in the XDMF view's references "file.h5:/group/dataset"
# (no escape exists: ParaView's "XDMF Reader" splits at the last ':' and
# looks for a file '/contact/contacts/on', the Xdmf3 readers split at the
# first and find no file 'b'), so the names that become part of them are
# refused before any work (exit 1, nothing written), the message naming the
# variable: the result file's name (&run output, -o) and the contact
# scenario's body and contact names. Before, each ran (exit 0) and wrote a
# view ParaView could not read. A ':' in the result's folder is not
# referenced and stays allowed.
set -u
slidesim=$1
# shellcheck source=support/cli_checks.sh
source "$(dirname "$0")/support/cli_checks.sh"

ball() {   # ball OUTPUT BODY CONTACT
  cat <<NML
&run scenario = 'contact', output = '$1' /
&solver duration = 0.05, output_step = 0.01 /
&shape name = 'floor', kind = 'plane' /
&shape name = 'ball', kind = 'sphere', radius = 0.1 /
&body name = '$2', mass = 0.2, solid_of = 'ball', position = 0, 0, 0.2 /
&contact name = '$3', shape_1 = 'floor', body_2 = '$2', shape_2 = 'ball', start = 'open' /
NML
}
ball 'file:name.h5' ball on_floor >"$work/file_name.nml"
run_case file_name 1 "&run: output = 'file:name.h5'" "the result file's name must not contain ':'"
ball 'body_name.h5' 'ball:1' on_floor >"$work/body_name.nml"
run_case body_name 1 "&body: name = 'ball:1'" "a body's name must not contain ':'"
ball 'contact_name.h5' ball 'on:floor' >"$work/contact_name.nml"
run_case contact_name 1 "&contact: name = 'on:floor'" "a contact's name must not contain ':'"
# A '/' or a lone '.' in a &body or &contact name: the name becomes a group
# of the result, and HDF5 reads '/' as a path separator ('on/floor' wrote a
# group 'on' holding 'floor') and '.' as the group itself. Refused likewise.
ball 'body_slash.h5' 'b/all' on_floor >"$work/body_slash.nml"
run_case body_slash 1 "&body: name = 'b/all'" "a body's name must not contain '/'"
ball 'contact_slash.h5' ball 'on/floor' >"$work/contact_slash.nml"
run_case contact_slash 1 "&contact: name = 'on/floor'" "a contact's name must not contain '/'"
ball 'body_dot.h5' '.' on_floor >"$work/body_dot.nml"
run_case body_dot 1 "&body: name = '.'" "a body's name must not be '.'"
# -o: the same refusal, nothing written
ball 'command_line.h5' ball on_floor >"$work/command_line.nml"
checks=$((checks + 1))
(cd "$work" && "$slidesim" -q -o 'x:y.h5' command_line.nml >command_line.out 2>command_line.err)
got=$?
[ "$got" = 1 ] || fail "-o x:y.h5: exit status $got, expected 1"
grep -qF -- "-o x:y.h5: the result file's name must not contain ':'" "$work/command_line.err" ||
  fail "-o x:y.h5: message: $(cat "$work/command_line.err")"
[ ! -e "$work/x:y.h5" ] && [ ! -e "$work/x:y.xmf" ] || fail "-o x:y.h5: a file was written"
# a folder with ':' in its name: the view names the file alone
mkdir "$work/a:b"
checks=$((checks + 1))
(cd "$work" && "$slidesim" -q -o 'a:b/in_folder.h5' command_line.nml >folder.out 2>folder.err)
got=$?
[ "$got" = 0 ] || fail "-o a:b/in_folder.h5: exit status $got, expected 0: $(cat "$work/folder.err")"
grep -q '>in_folder.h5:/contact/' "$work/a:b/in_folder.xmf" 2>/dev/null ||
  fail "-o a:b/in_folder.h5: the view does not name in_folder.h5 alone"
finish
