#!/bin/sh
# after.sh DONEFILE CMD... : wait for DONEFILE then run CMD
f=$1; shift
while [ ! -f $f ]; do sleep 10; done
sh -c "$*"
