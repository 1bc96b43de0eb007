def log = new File(basedir, 'build.log').text
// certify never fails on results; verify fails, naming the claimed feature that is not realised
assert log.contains('Basic Level: conformant')
assert log =~ /claimed E-ACCU-NSUM \(Table 9, [^)]*\) is not realised; cases not passed: E-ACCU-NSUM-001/
assert !log.contains('claimed E-ACCU-BSUM')
assert log.contains('BUILD FAILURE')
// the reports name the Maven command that reruns a case, not a ./fclcert launcher a Maven user does not have
def md = new File(basedir, 'target/fclcert-reports/report.md').text
// the run's seed too, so that the rerun sends the same disguise and fresh vectors
assert md.contains('reproduce: `mvn verify -Dfclcert.cases=E-ACCU-NSUM-001 -Dfclcert.seed=')
assert !md.contains('./fclcert certify')
assert new File(basedir, 'target/fclcert-reports/report.html').text.contains('mvn verify -Dfclcert.cases=E-ACCU-NSUM-001')
