#!/bin/sh
# Runs inside the HIL VM (tests/hil/vm/init.sh calls it from the 9p share): the vcan and
# gpio-sim HIL tests, with their results (the XML, each run's configs, telemetry and plant
# log) written back to the share.
export MRD_PLANT=/hil/bin/mrd-plant MRD_CONTROLLER=/hil/bin/mrd-controller
/hil/bin/gpiodetect
/hil/bin/mrd_hil_vm_tests --gtest_output=xml:/hil/results/hil_vm.xml
rc=$?
cp -r /tmp/mrd_hil_* /hil/results/ 2>/dev/null
exit $rc
