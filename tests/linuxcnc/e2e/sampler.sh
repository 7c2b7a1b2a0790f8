#!/bin/sh
# Started by the HAL file with loadusr: the sampled joints to the file $1 (halsampler writes
# to its standard output only).
exec halsampler >"$1"
