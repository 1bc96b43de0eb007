def log = new File(basedir, 'build.log').text
// the missing ';' after the term on line 9 is reported with its location in Maven's form
assert log =~ /\[ERROR\] .*broken\.fcl:\[(9|10),\d+\] error FCL-S\d{3}: /
assert log.contains('BUILD FAILURE')
// the findings are also written as a SARIF 2.1.0 log beside the build output, with the error's region
def sarif = new File(basedir, 'target/fclcert/check.sarif')
assert sarif.isFile()
assert sarif.text.contains('"version" : "2.1.0"')
assert sarif.text =~ /"ruleId" : "FCL-S\d{3}"/
assert sarif.text =~ /"startLine" : (9|10),/
