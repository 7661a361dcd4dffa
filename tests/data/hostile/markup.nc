(<script>alert(1)</script>)
(<img src=x onerror=alert(document.cookie)>)
G01 X<img src=x onerror=alert(1)> F100.
<b>G00</b> X1.
G00 X"><svg onload=alert(1)>
(" quotes ' apostrophes & ampersands </textarea></pre><!-- -->)
G00 X1. (javascript:alert(1))
<script src="https://example.invalid/x.js"></script>
G00 Y1. ; <iframe srcdoc="<script>parent.alert(1)</script>">
