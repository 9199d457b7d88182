#!/usr/bin/env bash
# cli_expect.sh CODE REGEX COMMAND...: runs COMMAND and passes if it exits with CODE and
# its combined output matches the extended regular expression REGEX.
set -u
expected_code=$1
regex=$2
shift 2
output=$("$@" 2>&1 </dev/null)
code=$?
status=0
if [ "$code" -ne "$expected_code" ]; then
  echo "FAIL: exit code $code, expected $expected_code"
  status=1
fi
if ! printf '%s' "$output" | tr '\n' ' ' | grep -Eq -- "$regex"; then
  echo "FAIL: output does not match: $regex"
  status=1
fi
if [ "$code" -ne 0 ] && [ "$(printf '%s\n' "$output" | grep -c .)" -gt 3 ]; then
  echo "FAIL: an error should be a short message, got $(printf '%s\n' "$output" | wc -l) lines"
  status=1
fi
echo "--- output of: $*"
printf '%s\n' "$output"
exit $status
