#!/bin/sh
# Runs inside the HIL VM (tests/hil/vm/init.sh calls it from the 9p share): the vcan and
# gpio-sim HIL tests, with their results written back to the share.
export MRD_PLANT=/hil/bin/mrd-plant MRD_CONTROLLER=/hil/bin/mrd-controller
/hil/bin/gpiodetect
/hil/bin/mrd_hil_vm_tests --gtest_output=xml:/hil/results/hil_vm.xml
