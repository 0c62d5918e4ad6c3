#!/usr/bin/env bash
# why.sh <dpgen> kernel.cpp...: triage with KEEP=1, then for each kernel the failing sizes and first messages.
d=$1; shift
wd=$(KEEP=1 ./triage.sh "$d" "$@" 2>&1 >/tmp/adv_why.out | sed -n 's/^work dir: //p')
cat /tmp/adv_why.out | grep -v '^---' | grep -v '^ACCEPTED='
for k in "$@"; do s=$(basename "$k" .cpp); [ -f $wd/$s/run.log ] || continue
  echo "== $s: failing: $(grep -h 'logged: n :=' $wd/$s/run.log | sort | uniq -c | tr -s ' \n' ' ')"
  grep -m4 -hE 'MESSAGE: (input|output)|<Jv,w>|differ|rejected' $wd/$s/run.log | sed 's/^ *//'
done
echo "workdir $wd"
